// Instanced scenes: transforms, the scene file reader, flattening (instancing.hpp).
#include "strahl/instancing.hpp"
#include "strahl/rng.hpp"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>

namespace strahl {

namespace {
using dmat = std::array<std::array<double, 4>, 3>;
dmat widen(const affine& a) {
    dmat d;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) d[r][c] = a.m[r][c];
    return d;
}
affine narrow(const dmat& d) {
    affine a;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) a.m[r][c] = float(d[r][c]);
    return a;
}
bool finite(const affine& a) {
    for (const auto& row : a.m)
        for (float v : row)
            if (!std::isfinite(v)) return false;
    return true;
}
}  // namespace

affine affine::translate(const vec3& t) {
    affine a;
    a.m[0][3] = t.x, a.m[1][3] = t.y, a.m[2][3] = t.z;
    return a;
}

affine affine::scale(const vec3& s) {
    affine a;
    a.m[0][0] = s.x, a.m[1][1] = s.y, a.m[2][2] = s.z;
    return a;
}

affine affine::rotate(int axis, float degrees) {
    const double r = double(degrees) * 3.14159265358979323846 / 180.0, c = std::cos(r), s = std::sin(r);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane turned: (y, z) about x, (z, x) about y, ...
    dmat d = widen(affine{});
    d[i][i] = c, d[i][j] = -s, d[j][i] = s, d[j][j] = c;
    return narrow(d);
}

affine operator*(const affine& a, const affine& b) {
    const dmat x = widen(a), y = widen(b);
    dmat d{};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) d[r][c] = x[r][0] * y[0][c] + x[r][1] * y[1][c] + x[r][2] * y[2][c];
        d[r][3] += x[r][3];
    }
    return narrow(d);
}

std::optional<affine> inverse(const affine& a) {
    if (!finite(a)) return std::nullopt;
    const dmat m = widen(a);
    // The adjugate of L over its determinant; the translation part is -L^-1 t.
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    double rows = 1.0;
    for (int r = 0; r < 3; ++r) rows *= std::sqrt(m[r][0] * m[r][0] + m[r][1] * m[r][1] + m[r][2] * m[r][2]);
    if (!(std::abs(det) > 1e-30 * rows)) return std::nullopt;
    dmat inv{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            inv[r][c] = (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) / det;
        }
    for (int r = 0; r < 3; ++r) inv[r][3] = -(inv[r][0] * m[0][3] + inv[r][1] * m[1][3] + inv[r][2] * m[2][3]);
    const affine result = narrow(inv);
    if (!finite(result)) return std::nullopt;
    return result;
}

aabb transformed(const aabb& box, const affine& a) {
    aabb out;
    if (box.is_empty()) return out;
    for (int k = 0; k < 8; ++k)
        out.grow(a.point({k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z}));
    return out;
}

std::uint64_t instanced_meshes::triangle_count() const {
    std::uint64_t n = 0;
    for (const instance& i : instances) n += meshes[i.mesh].triangle_count();
    return n;
}

std::vector<std::uint32_t> instanced_meshes::first_ids() const {
    std::vector<std::uint32_t> first(instances.size());
    std::uint64_t n = 0;
    for (std::size_t i = 0; i < instances.size(); ++i) first[i] = std::uint32_t(n), n += meshes[instances[i].mesh].triangle_count();
    return first;
}

aabb instanced_meshes::bounds() const {
    std::vector<aabb> mesh_boxes(meshes.size());
    for (std::size_t m = 0; m < meshes.size(); ++m) mesh_boxes[m] = meshes[m].bounds();
    aabb box;
    for (const instance& i : instances) box.grow(transformed(mesh_boxes[i.mesh], i.to_world));
    return box;
}

triangle_mesh instanced_meshes::flatten() const {
    triangle_mesh flat;
    std::size_t vertices = 0, triangles = 0;
    for (const instance& i : instances) vertices += meshes[i.mesh].positions.size(), triangles += meshes[i.mesh].triangle_count();
    flat.positions.reserve(vertices);
    flat.indices.reserve(triangles);
    for (const instance& i : instances) {
        const triangle_mesh& m = meshes[i.mesh];
        const auto base = std::uint32_t(flat.positions.size());
        for (const vec3& p : m.positions) flat.positions.push_back(i.to_world.point(p));
        for (const uvec3& t : m.indices) flat.indices.push_back(t + uvec3(base));
    }
    return flat;
}

std::size_t instanced_meshes::memory_bytes() const {
    std::size_t bytes = instances.size() * sizeof(instance);
    for (const triangle_mesh& m : meshes) bytes += m.positions.size() * sizeof(vec3) + m.indices.size() * sizeof(uvec3);
    return bytes;
}

std::size_t instanced_meshes::flattened_bytes() const {
    std::size_t bytes = 0;
    for (const instance& i : instances)
        bytes += meshes[i.mesh].positions.size() * sizeof(vec3) + meshes[i.mesh].indices.size() * sizeof(uvec3);
    return bytes;
}

namespace {
// The field's instances: instance (i, j) is `before`, then a turn about y by a pseudo-random angle, then
// `after`, then the move to its cell (i dx, 0, j dz).
void add_field(instanced_meshes& out, std::uint32_t mesh, int nx, int nz, float dx, float dz, std::uint32_t seed,
               const affine& before, const affine& after) {
    pcg32 random(seed);
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < nz; ++j) {
            const affine turn = affine::rotate(1, 360.0f * random.next_float());
            out.instances.push_back({mesh, affine::translate({float(i) * dx, 0.0f, float(j) * dz}) * after * turn * before});
        }
}

struct line_reader {
    const std::filesystem::path& file;
    int number = 0;
    std::vector<std::string> words{};
    std::size_t next = 1;

    [[noreturn]] void fail(const std::string& what) const {
        throw load_error(file.string() + ":" + std::to_string(number) + ": " + what);
    }
    bool more() const { return next < words.size(); }
    const std::string& word(const char* what) {
        if (!more()) fail(std::string("'") + words[0] + "' needs " + what);
        return words[next++];
    }
    float number_(const char* what) {
        const std::string& w = word(what);
        float v = 0.0f;
        const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
        if (ec != std::errc() || end != w.data() + w.size()) fail("'" + w + "' is not a number (" + what + ")");
        if (!std::isfinite(v) || std::abs(v) > max_coordinate) fail("'" + w + "' is out of range (" + what + ")");
        return v;
    }
    int count(const char* what, int lo, int hi) {
        const float v = number_(what);
        if (v != std::floor(v) || v < float(lo) || v > float(hi))
            fail(std::string(what) + " must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return int(v);
    }
    // TRANSFORM words up to the end of the line, composed in the order written.
    affine transform() {
        affine a;
        while (more()) {
            const std::string w = word("a transform");
            affine step;
            if (w == "translate") {
                const float x = number_("x"), y = number_("y"), z = number_("z");
                step = affine::translate({x, y, z});
            } else if (w == "scale") {
                const float x = number_("a scale");
                // One factor, or three.
                if (more() && words[next] != "translate" && words[next] != "scale" && words[next] != "rotate" && words[next] != "matrix") {
                    const float y = number_("y scale"), z = number_("z scale");
                    step = affine::scale({x, y, z});
                } else {
                    step = affine::scale(vec3(x));
                }
            } else if (w == "rotate") {
                const std::string& axis = word("an axis x, y or z");
                if (axis != "x" && axis != "y" && axis != "z") fail("rotate's axis must be x, y or z, not '" + axis + "'");
                step = affine::rotate(axis[0] - 'x', number_("degrees"));
            } else if (w == "matrix") {
                for (auto& row : step.m)
                    for (float& v : row) v = number_("twelve matrix entries");
            } else {
                fail("unknown transform '" + w + "' (translate, scale, rotate, matrix)");
            }
            a = step * a;
        }
        if (!inverse(a)) fail("the transform is singular (it cannot be inverted)");
        return a;
    }
};
}  // namespace

instanced_meshes load_instanced(const std::filesystem::path& file, std::ostream* log,
                                std::optional<std::array<float, 7>>* camera) {
    std::ifstream in(file);
    if (!in) throw load_error(file.string() + ": cannot be opened");
    instanced_meshes out;
    std::map<std::string, std::uint32_t> by_name;
    std::vector<aabb> mesh_boxes;  // each mesh's box, for the instances' extents
    line_reader reader{file};
    std::uint64_t triangles = 0;
    std::string text;
    while (std::getline(in, text)) {
        ++reader.number;
        if (const auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
        std::istringstream words(text);
        reader.words.clear();
        reader.next = 1;
        for (std::string w; words >> w;) reader.words.push_back(w);
        if (reader.words.empty()) continue;
        const std::string& key = reader.words[0];
        if (key == "mesh") {
            const std::string name = reader.word("a name and a path");
            const std::string path = reader.word("a path");
            if (reader.more()) reader.fail("'mesh' takes a name and a path, and nothing after them");
            if (by_name.count(name)) reader.fail("mesh '" + name + "' is named twice");
            const std::filesystem::path p = std::filesystem::path(path).is_absolute() ? std::filesystem::path(path)
                                                                                      : file.parent_path() / path;
            by_name[name] = std::uint32_t(out.meshes.size());
            out.meshes.push_back(load_mesh(p, log));
            out.names.push_back(name);
            mesh_boxes.push_back(out.meshes.back().bounds());
        } else if (key == "instance" || key == "field") {
            const std::string& name = reader.word("a mesh name");
            const auto it = by_name.find(name);
            if (it == by_name.end()) reader.fail("no mesh named '" + name + "' (a 'mesh' line must come first)");
            // The counts checked before anything is added: instances, and triangles for 32-bit ids.
            const auto add = [&](std::uint64_t k) {
                if (out.instances.size() + k > max_instances)
                    reader.fail("more than " + std::to_string(max_instances) + " instances");
                triangles += k * out.meshes[it->second].triangle_count();
                if (triangles > 0xFFFFFFFEull)
                    reader.fail(std::to_string(triangles) + " triangles in all, more than 32-bit primitive ids can number");
            };
            const std::size_t first_new = out.instances.size();
            if (key == "instance") {
                add(1);
                out.instances.push_back({it->second, reader.transform()});
            } else {
                const int nx = reader.count("NX", 1, 1024), nz = reader.count("NZ", 1, 1024);
                const float dx = reader.number_("DX"), dz = reader.number_("DZ");
                std::uint32_t seed = 1;
                if (reader.more() && std::isdigit(static_cast<unsigned char>(reader.words[reader.next][0])))
                    seed = std::uint32_t(reader.count("SEED", 0, 1 << 30));
                const affine after = reader.transform();
                add(std::uint64_t(nx) * std::uint64_t(nz));
                add_field(out, it->second, nx, nz, dx, dz, seed, affine{}, after);
            }
            // Each instance as placed holds to the course's smallest extent, as a mesh file does (the flattened
            // copy every structure but chapter 10's traces has the instance's size; the world box, which holds
            // every instance's, then holds to it too).
            for (std::size_t k = first_new; k < out.instances.size(); ++k) {
                const vec3 e = transformed(mesh_boxes[it->second], out.instances[k].to_world).extent();
                const float span = std::max({e.x, e.y, e.z});
                if (!(span >= min_extent)) reader.fail("mesh '" + name + "' as this line places it " + below_min_extent(span));
            }
        } else if (key == "camera") {
            std::array<float, 7> c{0, 0, 0, 0, 0, 0, 40.0f};
            for (int k = 0; k < 6; ++k) c[k] = reader.number_("the eye and the point looked at");
            if (reader.more()) c[6] = reader.number_("the field of view");
            if (reader.more()) reader.fail("'camera' takes six or seven numbers");
            if (!(c[6] > 0.0f && c[6] < 180.0f)) reader.fail("the field of view must lie in (0, 180) degrees");
            // The camera's basis needs a view direction not along +-y (its up).
            if (c[0] == c[3] && c[2] == c[5])
                reader.fail("the camera looks straight up or down, or at its own eye: move the eye off the vertical");
            if (camera) *camera = c;
        } else {
            reader.fail("unknown keyword '" + key + "' (mesh, instance, field, camera)");
        }
    }
    if (out.instances.empty()) throw load_error(file.string() + ": no instances (an 'instance' or 'field' line)");
    const aabb box = out.bounds();
    const vec3 far = glm::max(glm::abs(box.min), glm::abs(box.max));
    if (!is_finite(far) || std::max({far.x, far.y, far.z}) > max_coordinate)
        throw load_error(file.string() + ": a transformed vertex lies beyond " + std::to_string(max_coordinate) +
                         " (the largest coordinate the course accepts)");
    return out;
}

scene instanced_scene(instanced_meshes inst, std::string name, const std::optional<std::array<float, 7>>& camera) {
    if (inst.triangle_count() > max_flattened_triangles)
        throw load_error(name + ": " + std::to_string(inst.triangle_count()) + " triangles in all; the flattened copy "
                         "every structure but chapter 10's traces is limited to " + std::to_string(max_flattened_triangles));
    scene s;
    s.name = std::move(name);
    s.mesh = inst.flatten();
    s.materials = {material_desc{"diffuse", material_kind::diffuse, color(0.8f), 0.0f}};
    const aabb box = s.mesh.bounds();
    s.camera = frame_camera(box);
    if (camera) {
        s.camera.eye = {(*camera)[0], (*camera)[1], (*camera)[2]};
        s.camera.target = {(*camera)[3], (*camera)[4], (*camera)[5]};
        s.camera.vfov_degrees = (*camera)[6];
    }
    s.lights = {frame_light(box, s.camera)};
    s.instances = std::make_shared<const instanced_meshes>(std::move(inst));
    return s;
}

instanced_meshes make_field(triangle_mesh mesh, std::string name, int nx, int nz, float spacing, std::uint32_t seed) {
    const aabb box = mesh.bounds();
    const vec3 e = box.extent();
    const float step = spacing * std::max({e.x, e.y, e.z});
    instanced_meshes out;
    // The mesh centred on the origin, standing on y = 0; turned; moved to its cell.
    const vec3 c = box.centroid();
    out.meshes.push_back(std::move(mesh));
    out.names.push_back(std::move(name));
    add_field(out, 0, nx, nz, step, step, seed, affine::translate({-c.x, -box.min.y, -c.z}), affine{});
    return out;
}

}  // namespace strahl
