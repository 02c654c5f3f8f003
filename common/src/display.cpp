// The rasteriser: OSMesa (Mesa's off-screen OpenGL, llvmpipe in software) with the legacy fixed-function
// pipeline, used as an independent oracle for primary visibility and for drawing overlays.
//
// Pixel conventions: the viewport is the camera's image size and the matrices are the camera's own
// (view_matrix, projection_matrix), so GL samples each pixel at its centre (i + 0.5, j + 0.5), exactly where
// camera::pixel_ray shoots. GL's row 0 is at the bottom; every read-back is flipped so row 0 is at the TOP.
//
// Depth: OSMesa (llvmpipe) gives a 24-bit depth buffer here, so znear is pushed as far out as it can go
// without clipping anything visible (see choose_depth_range). Triangles behind the eye or straddling it are
// clipped by GL at the near plane. Limitation: geometry closer to the eye than 1e-6 zfar is clipped and
// missing from the id buffer (a ray tracer would see it), and depths are then coarse.
#include "strahl/display.hpp"
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <glm/gtc/type_ptr.hpp>
#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace strahl {
namespace {

// ---- one OSMesa context per thread, created on first use, bound to an RGBA8 buffer of the call's size ------
// Reusing the context keeps llvmpipe's compiled shaders (a fresh context costs ~10 ms) and avoids a small
// leak inside Mesa 22 that every create/make-current/destroy cycle incurs. Every call sets all the GL state
// it relies on, and leaves this context current on the calling thread.
class gl_context {
public:
    static gl_context& for_this_thread() {
        thread_local gl_context ctx;
        return ctx;
    }

    // Makes the context current with a fresh, cleared colour buffer of the given size.
    void bind(int width, int height) {
        if (width <= 0 || height <= 0) throw std::runtime_error("OSMesa: image size must be positive");
        GLint max_w = 0, max_h = 0;
        OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &max_w);
        OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &max_h);
        if ((max_w > 0 && width > max_w) || (max_h > 0 && height > max_h))
            throw std::runtime_error("OSMesa: image larger than the maximum " + std::to_string(max_w) + " x " +
                                     std::to_string(max_h));
        buffer_.assign(std::size_t(width) * height * 4, 0);
        if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width, height))
            throw std::runtime_error("OSMesa: cannot make the context current at " + std::to_string(width) + " x " +
                                     std::to_string(height));
        OSMesaPixelStore(OSMESA_Y_UP, 1);  // buffer row 0 is GL's bottom row, as glReadPixels gives it
        while (glGetError() != GL_NO_ERROR) {
        }  // forget errors of earlier calls on this thread
    }

    // The colour buffer, GL's bottom row first.
    const std::vector<std::uint8_t>& colour_buffer() const { return buffer_; }

    gl_context(const gl_context&) = delete;
    gl_context& operator=(const gl_context&) = delete;
    ~gl_context() {
        if (OSMesaGetCurrentContext() == ctx_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
        OSMesaDestroyContext(ctx_);
    }

private:
    gl_context() {
        // RGBA8 colour; ask for a 32-bit depth buffer, fall back to 24 bits (Mesa 22's llvmpipe gives 24).
        for (int depth_bits : {32, 24}) {
            const int attribs[] = {OSMESA_FORMAT,  OSMESA_RGBA, OSMESA_DEPTH_BITS, depth_bits,
                                   OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
            ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
            if (ctx_) return;
        }
        throw std::runtime_error("OSMesa: cannot create a context");
    }

    OSMesaContext ctx_ = nullptr;
    std::vector<std::uint8_t> buffer_;
};

// Exact, order-independent state for drawing ids: no lighting, blending, dithering, smoothing or multisampling.
void set_exact_state(const camera& cam, float znear, float zfar) {
    glViewport(0, 0, cam.width(), cam.height());
    glDisable(GL_LIGHTING);
    glDisable(GL_BLEND);
    glDisable(GL_DITHER);
    glDisable(GL_MULTISAMPLE);
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_POLYGON_SMOOTH);
    glDisable(GL_CULL_FACE);
    glDisable(GL_TEXTURE_2D);
    glShadeModel(GL_FLAT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);  // decodes to id 0 - 1 = invalid_id
    // The camera's own matrices.
    const mat4 projection = cam.projection_matrix(znear, zfar), view = cam.view_matrix();
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(projection));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(view));
}

// id + 1 as RGBA bytes (little end in red), so that the cleared colour (0, 0, 0, 0) means "no triangle".
void encode_id(std::uint32_t id, std::uint8_t* rgba) {
    const std::uint32_t code = id + 1u;
    for (int k = 0; k < 4; ++k) rgba[k] = std::uint8_t(code >> (8 * k));
}
std::uint32_t decode_id(const std::uint8_t* rgba) {
    const std::uint32_t code = std::uint32_t(rgba[0]) | std::uint32_t(rgba[1]) << 8 | std::uint32_t(rgba[2]) << 16 |
                               std::uint32_t(rgba[3]) << 24;
    return code - 1u;  // 0 wraps to invalid_id
}

// Draws unindexed triangles or lines, each primitive in its own flat code colour.
void draw_coded(GLenum mode, const std::vector<float>& xyz, const std::vector<std::uint8_t>& rgba) {
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, xyz.data());
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, rgba.data());
    glDrawArrays(mode, 0, GLsizei(xyz.size() / 3));
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glFinish();
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
        throw std::runtime_error("OSMesa: OpenGL error " + std::to_string(err));
}

// Reads the id codes back, flipping rows so row 0 is at the top.
std::vector<std::uint32_t> read_ids(const gl_context& gl, int w, int h) {
    const std::vector<std::uint8_t>& buf = gl.colour_buffer();
    std::vector<std::uint32_t> ids(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ids[std::size_t(y) * w + x] = decode_id(&buf[(std::size_t(h - 1 - y) * w + x) * 4]);
    return ids;
}

// Distance from p to the closest point of triangle abc (Ericson, "Real-Time Collision Detection", 2005, 5.1.5).
double point_triangle_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return glm::length(p - a);  // vertex region a
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return glm::length(p - b);  // vertex region b
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::length(p - (a + d1 / (d1 - d3) * ab));  // edge ab
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return glm::length(p - c);  // vertex region c
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::length(p - (a + d2 / (d2 - d6) * ac));  // edge ac
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
        return glm::length(p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b)));  // edge bc
    const double denom = 1.0 / (va + vb + vc);  // inside the face
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

// znear and zfar from the eye depth (distance along the forward axis) of the vertices. zfar lies just beyond
// the farthest vertex. znear must not clip anything visible: in front of the closest vertex when all lie in
// front of the eye; in any case at most d / sqrt(1 + tx^2 + ty^2), where d is the distance from the eye to the
// closest primitive (a visible point at distance >= d has depth >= that, tx and ty being the frustum's
// half-extents); never below 1e-6 zfar (the limitation: geometry nearer than that is clipped).
struct depth_range {
    float znear, zfar;
    bool visible;  // false when every vertex lies behind the eye
};
depth_range choose_depth_range(const std::vector<float>& xyz, const camera& cam, double closest_distance) {
    double lo = inf, hi = -inf;
    const glm::dvec3 eye(cam.eye()), fwd(cam.forward());
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
        const double z = glm::dot(fwd, glm::dvec3(xyz[i], xyz[i + 1], xyz[i + 2]) - eye);
        lo = std::min(lo, z), hi = std::max(hi, z);
    }
    if (!(hi > 0.0)) return {1.0f, 2.0f, false};
    const double zfar = hi * 1.01 + 1e-6;
    const double tx = double(cam.tan_half_fov()) * double(cam.aspect()), ty = double(cam.tan_half_fov());
    double znear = 0.99 * closest_distance / std::sqrt(1.0 + tx * tx + ty * ty);
    if (lo > 0.0) znear = std::max(znear, 0.99 * lo);
    znear = std::max(znear, 1e-6 * zfar);
    return {float(znear), float(zfar), true};
}

}  // namespace

// ---- rasterize ----------------------------------------------------------------------------------------------
raster_result rasterize(const triangle_mesh& mesh, const camera& cam) {
    const int w = cam.width(), h = cam.height();
    const std::size_t n = std::size_t(w) * h;
    raster_result r;
    r.width = w, r.height = h;
    r.colour = image(w, h, color(0.0f));
    r.ids.assign(n, invalid_id);
    r.depth.assign(n, inf);

    // Unindexed vertices and their code colours; triangles with non-finite vertices are left out.
    std::vector<float> xyz;
    std::vector<std::uint8_t> rgba;
    xyz.reserve(mesh.indices.size() * 9);
    rgba.reserve(mesh.indices.size() * 12);
    for (std::size_t t = 0; t < mesh.indices.size(); ++t) {
        const uvec3 idx = mesh.indices[t];
        for (int k = 0; k < 3; ++k)
            if (idx[k] >= mesh.positions.size())
                throw std::runtime_error("rasterize: triangle " + std::to_string(t) + " names vertex " +
                                         std::to_string(idx[k]) + " of " + std::to_string(mesh.positions.size()));
        const std::array<vec3, 3> v = mesh.triangle(t);
        if (!is_finite(v[0]) || !is_finite(v[1]) || !is_finite(v[2])) continue;
        std::uint8_t code[4];
        encode_id(std::uint32_t(t), code);
        for (const vec3& p : v) {
            xyz.insert(xyz.end(), {p.x, p.y, p.z});
            rgba.insert(rgba.end(), code, code + 4);
        }
    }
    if (xyz.empty()) return r;  // nothing to draw: all invalid
    double closest = inf;
    const glm::dvec3 eye(cam.eye());
    for (std::size_t i = 0; i < xyz.size(); i += 9)
        closest = std::min(closest, point_triangle_distance(eye, glm::dvec3(xyz[i], xyz[i + 1], xyz[i + 2]),
                                                            glm::dvec3(xyz[i + 3], xyz[i + 4], xyz[i + 5]),
                                                            glm::dvec3(xyz[i + 6], xyz[i + 7], xyz[i + 8])));
    const depth_range range = choose_depth_range(xyz, cam, closest);
    if (!range.visible) return r;

    // (a) The triangle-id buffer, with a depth test.
    gl_context& gl = gl_context::for_this_thread();
    gl.bind(w, h);
    set_exact_state(cam, range.znear, range.zfar);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw_coded(GL_TRIANGLES, xyz, rgba);
    r.ids = read_ids(gl, w, h);

    // (b) Depth: window depth -> NDC z -> eye depth (glm::perspective, z in [-1, 1]) -> distance along the
    //     normalised pixel-centre ray.
    std::vector<GLuint> window_depth(n);
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, window_depth.data());
    const double zn = range.znear, zf = range.zfar;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (r.ids[i] == invalid_id) continue;
            const double d = double(window_depth[std::size_t(h - 1 - y) * w + x]) / 4294967295.0;
            const double z_ndc = 2.0 * d - 1.0;
            const double eye_depth = 2.0 * zf * zn / ((zf + zn) - z_ndc * (zf - zn));
            const vec3 dir = cam.pixel_ray(x, y).dir;
            r.depth[i] = float(eye_depth / double(glm::dot(dir, cam.forward())));
        }

    // (c) The colour image: grey by facing ratio |cos| between the pixel-centre ray and the triangle's normal.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint32_t id = r.ids[std::size_t(y) * w + x];
            if (id == invalid_id || id >= mesh.indices.size()) continue;
            const std::array<vec3, 3> v = mesh.triangle(id);
            const vec3 nrm = glm::cross(v[1] - v[0], v[2] - v[0]);
            const float len = glm::length(nrm);
            const float facing = len > 0.0f ? std::fabs(glm::dot(nrm / len, cam.pixel_ray(x, y).dir)) : 0.0f;
            r.colour.at(x, y) = color(0.1f + 0.8f * facing);
        }
    return r;
}

// ---- draw_lines ---------------------------------------------------------------------------------------------
// Draws segment index + 1 as a code colour into an RGBA8 buffer (no depth test, later segments on top), then
// writes each covered pixel of img with its segment's colour: img stays linear, any colour (even > 1) is exact.
void draw_lines(image& img, const camera& cam, const std::vector<line_segment>& lines, float width) {
    if (img.width != cam.width() || img.height != cam.height())
        throw std::invalid_argument("draw_lines: the image and the camera differ in size");
    std::vector<float> xyz;
    std::vector<std::uint8_t> rgba;
    for (std::size_t s = 0; s < lines.size(); ++s) {
        if (!is_finite(lines[s].a) || !is_finite(lines[s].b)) continue;
        std::uint8_t code[4];
        encode_id(std::uint32_t(s), code);
        for (const vec3& p : {lines[s].a, lines[s].b}) {
            xyz.insert(xyz.end(), {p.x, p.y, p.z});
            rgba.insert(rgba.end(), code, code + 4);
        }
    }
    if (xyz.empty()) return;
    const depth_range range = choose_depth_range(xyz, cam, 0.0);  // no depth test: any small znear will do
    if (!range.visible) return;

    gl_context& gl = gl_context::for_this_thread();
    gl.bind(img.width, img.height);
    set_exact_state(cam, range.znear, range.zfar);
    glDisable(GL_DEPTH_TEST);
    glLineWidth(std::max(width, 1.0f));
    glClear(GL_COLOR_BUFFER_BIT);
    draw_coded(GL_LINES, xyz, rgba);

    // Composite the covered pixels into img.
    const std::vector<std::uint32_t> ids = read_ids(gl, img.width, img.height);
    for (std::size_t i = 0; i < ids.size(); ++i)
        if (ids[i] < lines.size()) img.pixels[i] = lines[ids[i]].c;
}

std::vector<line_segment> box_wireframe(const aabb& box, color c) {
    if (box.is_empty()) return {};
    // Corner k has x from bit 0, y from bit 1, z from bit 2; an edge joins corners differing in one bit.
    auto corner = [&](int k) {
        return vec3(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z);
    };
    std::vector<line_segment> edges;
    for (int k = 0; k < 8; ++k)
        for (int bit : {1, 2, 4})
            if (!(k & bit)) edges.push_back({corner(k), corner(k | bit), c});
    return edges;
}

}  // namespace strahl
