// SPDX-License-Identifier: Apache-2.0
// read_gltf: glTF 2.0 -> polygon soup (gltf_reader.h). TinyGLTF parses the JSON, the GLB container
// and the buffers (through hmcr's file reader, so that a buffer is a regular file of bounded
// size); hmcr checks every index and every accessor's bytes against its buffer before it reads
// them, so that memory is bounded by the files' sizes whatever the counts say.
#include "meshes/gltf_reader.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "common/text_file.h"
#include "meshes/fan_quads.h"
#include "meshes/gltf_materials.h"
#include "meshes/single_precision.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// The extensions a file may require: the one hmcr reads, and one of textures, which it skips.
constexpr std::string_view kKnownRequired[] = {"KHR_materials_emissive_strength",
                                               "KHR_texture_transform"};

// The first line of TinyGLTF's messages (it ends each with a newline).
std::string first_line(const std::string& text) {
    std::size_t begin = text.find_first_not_of("\r\n");
    if (begin == std::string::npos) return "not a glTF file hmcr can read";
    return text.substr(begin, text.find_first_of("\r\n", begin) - begin);
}

// TinyGLTF's file callbacks: a buffer is found only beside the glTF file (TinyGLTF also looks
// in the working folder) and is read as hmcr reads every file.
struct GltfFiles {
    std::string folder;  // with its trailing separator, or "" for the working folder
};

bool gltf_file_exists(const std::string& path, void* user) {
    const auto* files = static_cast<const GltfFiles*>(user);
    std::error_code ec;
    return path.rfind(files->folder, 0) == 0 && fs::is_regular_file(path, ec);
}

std::string gltf_expand_path(const std::string& path, void*) { return path; }

bool gltf_read_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                    void*) {
    try {
        const std::string bytes = read_text_file(path, std::numeric_limits<std::uint32_t>::max());
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& e) {
        *err = e.what();
        return false;
    }
}

bool gltf_write_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
}

// Images are not read (gltf_materials.h): their bytes are dropped undecoded.
bool gltf_skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                     const unsigned char*, int, void*) {
    return true;
}

tinygltf::Model parse(const fs::path& path, std::vector<std::string>& warnings) {
    const std::string bytes = read_text_file(path, std::numeric_limits<std::uint32_t>::max());
    GltfFiles files;
    files.folder = path.parent_path().empty() ? "" : path.parent_path().string() + "/";
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(
        {&gltf_file_exists, &gltf_expand_path, &gltf_read_file, &gltf_write_file, &files});
    loader.SetImageLoader(&gltf_skip_image, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const std::string base = path.parent_path().string();
    const bool binary = bytes.rfind("glTF", 0) == 0;
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data,
                                                         unsigned(bytes.size()), base)
                           : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                                        unsigned(bytes.size()), base);
    if (!ok || !err.empty()) throw InputError(path.string(), first_line(err));
    for (std::size_t begin = 0; begin < warn.size();) {
        std::size_t end = warn.find('\n', begin);
        if (end == std::string::npos) end = warn.size();
        if (end > begin) warnings.push_back(path.string() + ": " + warn.substr(begin, end - begin));
        begin = end + 1;
    }
    for (const std::string& name : model.extensionsRequired) {
        if (std::find(std::begin(kKnownRequired), std::end(kKnownRequired), name) ==
            std::end(kKnownRequired)) {
            throw InputError(
                path.string(),
                fmt::format("requires the extension {}, which hmcr does not read", quote(name)));
        }
    }
    return model;
}

// An accessor's elements, checked to lie in its buffer.
struct Elements {
    const unsigned char* first = nullptr;
    std::size_t count = 0, stride = 0;
    int component = 0;  // TINYGLTF_COMPONENT_TYPE_*
};

class GltfReader {
public:
    GltfReader(const fs::path& gltf, const GltfOptions& options)
        : m_path(gltf.string()), m_options(options) {
        m_soup.files.push_back(gltf);
        m_soup.item_names[0] = "face";
        m_soup.no_material = "its primitive has no material";
        m_model = parse(gltf, m_soup.warnings);
        read_gltf_materials(m_model, 0, m_soup);
    }

    PolygonSoup read() {
        m_placed.assign(m_model.nodes.size(), false);
        place_all();
        return std::move(m_soup);
    }

private:
    [[noreturn]] void fail(const std::string& what, std::size_t index,
                           const std::string& why) const {
        throw InputError(fmt::format("{}: {}[{}]", m_path, what, index), why);
    }

    // The nodes of the default scene (or the first), else every node that is no node's child.
    std::vector<int> roots() const {
        if (!m_model.scenes.empty()) {
            const int scene = m_model.defaultScene >= 0 ? m_model.defaultScene : 0;
            if (std::size_t(scene) >= m_model.scenes.size()) {
                throw InputError(m_path, fmt::format("scene {} does not exist", scene));
            }
            return m_model.scenes[std::size_t(scene)].nodes;
        }
        std::vector<bool> child(m_model.nodes.size(), false);
        for (const tinygltf::Node& n : m_model.nodes) {
            for (const int c : n.children) {
                if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
            }
        }
        std::vector<int> out;
        for (std::size_t k = 0; k < child.size(); ++k) {
            if (!child[k]) out.push_back(int(k));
        }
        return out;
    }

    Eigen::Affine3d local(const tinygltf::Node& n, std::size_t k) const {
        Eigen::Affine3d m = Eigen::Affine3d::Identity();
        if (!n.matrix.empty()) {
            if (n.matrix.size() != 16) fail("nodes", k, "matrix needs 16 numbers");
            Eigen::Matrix4d full;
            for (int i = 0; i < 16; ++i) full(i % 4, i / 4) = n.matrix[std::size_t(i)];
            m.matrix() = full;
            return m;
        }
        if (!n.translation.empty()) {
            if (n.translation.size() != 3) fail("nodes", k, "translation needs 3 numbers");
            m.translate(Eigen::Vector3d(n.translation[0], n.translation[1], n.translation[2]));
        }
        if (!n.rotation.empty()) {
            if (n.rotation.size() != 4) fail("nodes", k, "rotation needs 4 numbers");
            const Eigen::Quaterniond q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
            if (!(q.norm() > 0)) fail("nodes", k, "rotation is not a unit quaternion");
            m.rotate(q.normalized());
        }
        if (!n.scale.empty()) {
            if (n.scale.size() != 3) fail("nodes", k, "scale needs 3 numbers");
            m.scale(Eigen::Vector3d(n.scale[0], n.scale[1], n.scale[2]));
        }
        return m;
    }

    // A mesh where a node places it.
    struct Placement {
        std::size_t mesh;
        Eigen::Affine3d transform;
        bool moved;  // the transform is not the identity
    };

    // The meshes the nodes of the scene place, each under its parent's transformation, depth
    // first with a stack of its own: a chain of a million nodes is a few lines of JSON.
    std::vector<Placement> placements() {
        struct Placing {
            int node;
            Eigen::Affine3d parent;
            bool moved;
        };
        std::vector<Placing> stack;
        std::vector<Placement> out;
        const std::vector<int> first = roots();
        for (auto r = first.rbegin(); r != first.rend(); ++r) {
            stack.push_back({*r, Eigen::Affine3d::Identity(), false});
        }
        while (!stack.empty()) {
            const Placing at = stack.back();
            stack.pop_back();
            if (at.node < 0 || std::size_t(at.node) >= m_model.nodes.size()) {
                throw InputError(m_path, fmt::format("node {} does not exist", at.node));
            }
            const std::size_t k = std::size_t(at.node);
            if (m_placed[k]) fail("nodes", k, "is reached twice: a node has one parent");
            m_placed[k] = true;
            const tinygltf::Node& n = m_model.nodes[k];
            const bool own = !n.matrix.empty() || !n.translation.empty() || !n.rotation.empty() ||
                             !n.scale.empty();
            const Eigen::Affine3d transform = own ? at.parent * local(n, k) : at.parent;
            if (!transform.matrix().allFinite()) {
                fail("nodes", k, "its transformation is not finite");
            }
            const bool moved = at.moved || own;
            if (n.mesh >= 0) {
                if (std::size_t(n.mesh) >= m_model.meshes.size()) {
                    throw InputError(m_path, fmt::format("mesh {} does not exist", n.mesh));
                }
                out.push_back({std::size_t(n.mesh), transform, moved});
            }
            for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) {
                stack.push_back({*c, transform, moved});
            }
        }
        return out;
    }

    // An accessor's count, checked to lie in its buffer; 0 for one that does not exist (reading
    // it then says so).
    std::uint64_t count_of(int accessor) const {
        if (accessor < 0 || std::size_t(accessor) >= m_model.accessors.size()) return 0;
        const int type = m_model.accessors[std::size_t(accessor)].type;
        return elements(accessor, "", type).count;
    }

    // Nodes may place one mesh any number of times: what they place is counted first, and
    // refused above the limits before anything is read.
    void check_size(const std::vector<Placement>& placed) const {
        std::uint64_t triangles = 0, vertices = 0;
        for (const Placement& at : placed) {
            for (const tinygltf::Primitive& p : m_model.meshes[at.mesh].primitives) {
                const auto position = p.attributes.find("POSITION");
                const std::uint64_t v =
                    position == p.attributes.end() ? 0 : count_of(position->second);
                const std::uint64_t corners = p.indices >= 0 ? count_of(p.indices) : v;
                vertices += v;
                if (p.mode == TINYGLTF_MODE_TRIANGLES) {
                    triangles += corners / 3;
                } else if (corners >= 3) {
                    triangles += corners - 2;
                }
            }
            if (triangles > m_options.max_polygons || vertices > 3 * m_options.max_polygons) {
                throw InputError(m_path,
                                 fmt::format("its nodes place more than {} triangles or {} "
                                             "vertices: hmcr reads no more",
                                             m_options.max_polygons, 3 * m_options.max_polygons));
            }
        }
    }

    void place_all() {
        const std::vector<Placement> placed = placements();
        check_size(placed);
        for (const Placement& at : placed) mesh(at.mesh, at.transform, at.moved);
    }

    void mesh(std::size_t index, const Eigen::Affine3d& transform, bool moved) {
        const tinygltf::Mesh& mesh = m_model.meshes[index];
        const bool flip = moved && transform.linear().determinant() < 0;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string where = fmt::format("meshes[{}].primitives[{}]", index, p);
            primitive(mesh.primitives[p], where, transform, moved, flip);
        }
    }

    Elements elements(int accessor, const std::string& where, int type) const {
        if (accessor < 0 || std::size_t(accessor) >= m_model.accessors.size()) {
            throw InputError(m_path,
                             fmt::format("{}: accessor {} does not exist", where, accessor));
        }
        const std::size_t a = std::size_t(accessor);
        const tinygltf::Accessor& acc = m_model.accessors[a];
        if (acc.sparse.isSparse) fail("accessors", a, "sparse accessors are not read");
        if (acc.type != type) fail("accessors", a, fmt::format("has the wrong type for {}", where));
        if (acc.bufferView < 0 || std::size_t(acc.bufferView) >= m_model.bufferViews.size()) {
            fail("accessors", a, "needs a bufferView");
        }
        const tinygltf::BufferView& view = m_model.bufferViews[std::size_t(acc.bufferView)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= m_model.buffers.size()) {
            fail("bufferViews", std::size_t(acc.bufferView), "needs a buffer");
        }
        const std::vector<unsigned char>& buffer = m_model.buffers[std::size_t(view.buffer)].data;
        const int component_bytes =
            tinygltf::GetComponentSizeInBytes(std::uint32_t(acc.componentType));
        const int components = tinygltf::GetNumComponentsInType(std::uint32_t(acc.type));
        if (component_bytes <= 0 || components <= 0) fail("accessors", a, "has an unknown type");
        const std::size_t size = std::size_t(component_bytes) * std::size_t(components);
        const std::size_t stride = view.byteStride == 0 ? size : view.byteStride;
        const bool view_fits =
            view.byteOffset <= buffer.size() && view.byteLength <= buffer.size() - view.byteOffset;
        const bool fits = view_fits && stride >= size && acc.byteOffset <= view.byteLength &&
                          (acc.count == 0 ||
                           (size <= view.byteLength - acc.byteOffset &&
                            (acc.count - 1) <= (view.byteLength - acc.byteOffset - size) / stride));
        if (!fits) fail("accessors", a, "its elements do not lie in its buffer view and buffer");
        return {buffer.data() + view.byteOffset + acc.byteOffset, acc.count, stride,
                acc.componentType};
    }

    // The corners of the primitive's triangles, as indices into its positions.
    std::vector<std::uint32_t> indices(const tinygltf::Primitive& p, std::size_t vertices,
                                       const std::string& where) const {
        std::vector<std::uint32_t> out;
        if (p.indices < 0) {
            for (std::size_t i = 0; i < vertices; ++i) out.push_back(std::uint32_t(i));
            return out;
        }
        const Elements e = elements(p.indices, where + " indices", TINYGLTF_TYPE_SCALAR);
        out.reserve(e.count);
        for (std::size_t i = 0; i < e.count; ++i) {
            const unsigned char* at = e.first + i * e.stride;
            std::uint32_t index = 0;
            if (e.component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                index = *at;
            } else if (e.component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                std::uint16_t v;
                std::memcpy(&v, at, sizeof v);
                index = v;
            } else if (e.component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
                std::memcpy(&index, at, sizeof index);
            } else {
                fail("accessors", std::size_t(p.indices), "indices must be unsigned integers");
            }
            if (index >= vertices) {
                fail("accessors", std::size_t(p.indices),
                     fmt::format("index {} is out of range ({} vertices)", index, vertices));
            }
            out.push_back(index);
        }
        return out;
    }

    // The primitive's triangles (as the specification makes them of a strip or a fan).
    std::vector<std::array<std::uint32_t, 3>> triangles(const std::vector<std::uint32_t>& v,
                                                        int mode, const std::string& where) const {
        std::vector<std::array<std::uint32_t, 3>> out;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (v.size() % 3 != 0) {
                throw InputError(m_path,
                                 fmt::format("{}: {} indices are not triangles", where, v.size()));
            }
            for (std::size_t i = 0; i + 2 < v.size(); i += 3)
                out.push_back({v[i], v[i + 1], v[i + 2]});
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (std::size_t i = 0; i + 2 < v.size(); ++i) {
                out.push_back(i % 2 == 0 ? std::array{v[i], v[i + 1], v[i + 2]}
                                         : std::array{v[i + 1], v[i], v[i + 2]});
            }
        } else {
            for (std::size_t i = 1; i + 1 < v.size(); ++i) out.push_back({v[i], v[i + 1], v[0]});
        }
        return out;
    }

    void primitive(const tinygltf::Primitive& p, const std::string& where,
                   const Eigen::Affine3d& transform, bool moved, bool flip) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            m_soup.warnings.push_back(
                fmt::format("{}: {}: points or lines (mode {}) skipped", m_path, where, p.mode));
            return;
        }
        const auto position = p.attributes.find("POSITION");
        if (position == p.attributes.end()) {
            throw InputError(m_path, where + ": no POSITION attribute");
        }
        const Elements e = elements(position->second, where + " POSITION", TINYGLTF_TYPE_VEC3);
        if (e.component != TINYGLTF_COMPONENT_TYPE_FLOAT) {
            fail("accessors", std::size_t(position->second), "POSITION must be float");
        }
        if (p.material >= 0 && std::size_t(p.material) >= m_soup.materials.size()) {
            throw InputError(m_path,
                             fmt::format("{}: material {} does not exist", where, p.material));
        }
        const std::size_t first = m_soup.positions.size();
        std::vector<Eigen::Vector3d> local(e.count);
        for (std::size_t i = 0; i < e.count; ++i) {
            std::array<float, 3> xyz;
            std::memcpy(xyz.data(), e.first + i * e.stride, sizeof xyz);
            for (int c = 0; c < 3; ++c) {
                if (!std::isfinite(xyz[std::size_t(c)])) {
                    fail("accessors", std::size_t(position->second), "a position is not finite");
                }
                local[i][c] = widen_float(xyz[std::size_t(c)]);
            }
            m_soup.positions.push_back(moved ? Eigen::Vector3d(transform * local[i]) : local[i]);
        }
        const auto tris = triangles(indices(p, e.count, where), p.mode, where);
        const std::int32_t material = p.material >= 0 ? p.material : PolygonSoup::kNoMaterial;
        std::vector<std::uint32_t> corners;
        join_fan_quads(tris, local, [&](std::span<const std::uint32_t> polygon) {
            corners.assign(polygon.begin(), polygon.end());
            if (flip) std::reverse(corners.begin() + 1, corners.end());  // turned over
            for (std::uint32_t& c : corners) c += std::uint32_t(first);
            m_soup.add_polygon(corners, material, {0, ++m_faces});
        });
    }

    std::string m_path;
    GltfOptions m_options;
    PolygonSoup m_soup;
    tinygltf::Model m_model;
    std::vector<bool> m_placed;  // by node
    std::uint32_t m_faces = 0;   // placed so far
};

}  // namespace

PolygonSoup read_gltf(const fs::path& gltf, const GltfOptions& options) {
    return GltfReader(gltf, options).read();
}

}  // namespace hmcr
