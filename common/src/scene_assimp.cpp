// The scene loader's steps 4 to 6, for every format but PLY (scene.cpp's top comment lists the steps):
// assimp reads the file with no post-processing; every face is checked (faces assimp dropped, indices,
// polygon size, NaN/Inf in referenced vertices) before any post-process touches them; assimp triangulates;
// the meshes are gathered in node order, their corners welded where exactly equal.
// Reference: assimp 5.2 documentation, https://assimp-docs.readthedocs.io (Importer, aiScene, aiNode).
#include "scene_detail.hpp"
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <utility>
#include <vector>

namespace strahl::scene_detail {

namespace {

// ---- After assimp reads the file: indices in range, referenced vertices finite, polygons of a size
// assimp can triangulate, and (glTF) every face the file holds, before any post-process touches them.
void check_raw_meshes(const std::filesystem::path& file, const aiScene& s, const gltf_expectation& expect) {
    if (expect.faces.size() == s.mNumMeshes) {
        for (unsigned m = 0; m < s.mNumMeshes; ++m)
            if (expect.faces[m] >= 0 && (long long)s.mMeshes[m]->mNumFaces < expect.faces[m])
                fail(file, expect.names[m] + ": " + with_thousands(std::size_t(expect.faces[m] - s.mMeshes[m]->mNumFaces)) +
                               " of its " + with_thousands(std::size_t(expect.faces[m])) +
                               " faces refer to a vertex beyond its " + with_thousands(s.mMeshes[m]->mNumVertices) +
                               " vertices (index out of range)");
    }
    for (unsigned m = 0; m < s.mNumMeshes; ++m) {
        const aiMesh& mesh = *s.mMeshes[m];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            const std::string which = "face " + with_thousands(f) + " of mesh " + std::to_string(m);
            if (face.mNumIndices == 0)  // assimp 5.2's triangulation aborts on these
                fail(file, which + " has no vertices");
            if (face.mNumIndices > max_polygon_corners) fail(file, which + " " + too_many_corners(face.mNumIndices));
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                const unsigned idx = face.mIndices[k];
                if (idx >= mesh.mNumVertices)
                    fail(file, which + " refers to vertex " + std::to_string(idx) + ", but the mesh has " +
                                   with_thousands(mesh.mNumVertices) + " vertices (index out of range)");
                const aiVector3D& p = mesh.mVertices[idx];
                if (!is_finite(vec3(p.x, p.y, p.z)))
                    fail(file, "vertex " + with_thousands(idx) + " of mesh " + std::to_string(m) +
                                   " has a non-finite coordinate (NaN or Inf)");
            }
        }
    }
}

// ---- Meshes in node order with accumulated transforms, walked without recursion (depth first, a node's
// own meshes before its children). Each mesh instance's corners are welded where bit-identical.
struct gatherer {
    const aiScene& scene;
    triangle_mesh out;
    std::size_t skipped = 0;  // points and lines

    void add(const aiNode& node, const aiMatrix4x4& world) {
        // Exactly the identity: aiMatrix4x4::IsIdentity allows 0.01 off, which would drop a small translation.
        const bool identity = world == aiMatrix4x4();
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
            triangle_mesh part;
            welder weld(part);
            for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
                const aiFace& face = mesh.mFaces[f];
                if (face.mNumIndices != 3) { ++skipped; continue; }
                uvec3 tri;
                for (int k = 0; k < 3; ++k) {
                    const unsigned v = face.mIndices[k];
                    const aiVector3D p = identity ? mesh.mVertices[v] : world * mesh.mVertices[v];
                    weld.begin(vec3(p.x, p.y, p.z));
                    if (mesh.mNormals) weld.add(&mesh.mNormals[v].x, 3);
                    for (unsigned c = 0; c < AI_MAX_NUMBER_OF_TEXTURECOORDS && mesh.mTextureCoords[c]; ++c)
                        weld.add(&mesh.mTextureCoords[c][v].x, 3);
                    for (unsigned c = 0; c < AI_MAX_NUMBER_OF_COLOR_SETS && mesh.mColors[c]; ++c)
                        weld.add(&mesh.mColors[c][v].r, 4);
                    tri[k] = weld.index();
                }
                part.indices.push_back(tri);
            }
            out.append(part);
        }
    }
    void walk(const aiNode& root) {
        // The root's transform as the recursive walk had it, identity times the node's (bit for bit the same
        // world transforms as before).
        std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{&root, aiMatrix4x4() * root.mTransformation}};
        while (!stack.empty()) {
            const auto [node, world] = stack.back();
            stack.pop_back();
            add(*node, world);
            for (unsigned c = node->mNumChildren; c-- > 0;)  // pushed in reverse: visited in order
                stack.emplace_back(node->mChildren[c], world * node->mChildren[c]->mTransformation);
        }
    }
};

}  // namespace

triangle_mesh assimp_mesh(const std::filesystem::path& file, const gltf_expectation& expect, std::size_t& skipped) {
    // Steps 4 to 6: read, check, triangulate, gather.
    Assimp::Importer importer;
    const aiScene* s = importer.ReadFile(file.string(), 0);
    if (!s) fail(file, std::string("cannot be read (assimp: ") + importer.GetErrorString() + ")");
    if ((s->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !s->mRootNode || s->mNumMeshes == 0)
        fail(file, "contains no triangles (no meshes found; malformed or not a mesh file)");
    check_raw_meshes(file, *s, expect);
    s = importer.ApplyPostProcessing(aiProcess_Triangulate);
    if (!s) fail(file, std::string("cannot be processed (assimp: ") + importer.GetErrorString() + ")");
    gatherer g{*s, {}, 0};
    g.walk(*s->mRootNode);
    skipped = g.skipped;
    for (const vec3& p : g.out.positions)
        if (!is_finite(p)) fail(file, "a node transform makes a coordinate non-finite (NaN or Inf)");
    return std::move(g.out);
}

}  // namespace strahl::scene_detail
