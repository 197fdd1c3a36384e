// SPDX-License-Identifier: Apache-2.0
#include "rays/embree_scene.h"

#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace hmcr {

struct EmbreeScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::string error;  // first error reported by Embree's callback
    // The geometry, shared with Embree. Ours rather than Embree's own buffers so that they come
    // from operator new, which the hmcr executable backs with huge pages: Embree's allocations
    // are a large share of a million-patch solve's page faults (docs/performance.md, "Memory of
    // the 10^6-patch office"). The vertices end in 4 floats of padding, which Embree's 16-byte
    // loads may read.
    std::vector<float> vertices;
    std::vector<unsigned> indices;

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    // Here rather than in ~EmbreeScene, so that a constructor that throws (an index out of
    // range, an Embree error) releases them too.
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

namespace {

void on_embree_error(void* user, RTCError code, const char* message) {
    auto* impl = static_cast<EmbreeScene::Impl*>(user);
    if (impl->error.empty()) {
        impl->error = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
    }
}

void throw_if_failed(const EmbreeScene::Impl& impl, const char* step) {
    if (!impl.error.empty()) throw std::runtime_error(std::string(step) + ": " + impl.error);
}

constexpr float kInf = std::numeric_limits<float>::infinity();

// One closest-hit query from origin o along direction d, ignoring hits closer than tnear.
RTCRayHit intersect(RTCScene scene, RTCIntersectContext& context, float ox, float oy, float oz,
                    float dx, float dy, float dz, float tnear) {
    RTCRayHit rh;
    rh.ray.org_x = ox;
    rh.ray.org_y = oy;
    rh.ray.org_z = oz;
    rh.ray.dir_x = dx;
    rh.ray.dir_y = dy;
    rh.ray.dir_z = dz;
    rh.ray.tnear = tnear;
    rh.ray.tfar = kInf;
    rh.ray.time = 0;
    rh.ray.mask = ~0u;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    return rh;
}

RTCRayHit intersect(RTCScene scene, const Vec3& origin, const Vec3& direction, double tnear) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    return intersect(scene, context, float(origin.x()), float(origin.y()), float(origin.z()),
                     float(direction.x()), float(direction.y()), float(direction.z()),
                     float(tnear));
}

}  // namespace

void set_tracing_float_mode() {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
}

// Both scenes are counted first and written straight into the buffers Embree reads: vectors
// grown corner by corner and then copied would hold a second copy of the geometry while the
// BVH is built, the peak of a large solve.
EmbreeScene::EmbreeScene(const std::vector<Patch>& patches) : m_impl(std::make_unique<Impl>()) {
    std::size_t corners = 0;
    for (const Patch& p : patches) corners += p.corner_count;
    build_patches(patches, corners, [&](float* vertex, unsigned* index) {
        unsigned base = 0;
        for (std::uint32_t i = 0; i < patches.size(); ++i) {
            const Patch& p = patches[i];
            for (int k = 0; k < p.corner_count; ++k) {
                for (int c = 0; c < 3; ++c) *vertex++ = float(p.corner[k][c]);
            }
            const unsigned v[4] = {base, base + 1, base + 2, base + 3};
            add_patch_triangles(v, p.is_quad(), index);
            base += unsigned(p.corner_count);
        }
    });
}

EmbreeScene::EmbreeScene(const PatchSet& set) : m_impl(std::make_unique<Impl>()) {
    const std::vector<Patch>& patches = set.patches;
    const FaceVertices& mesh = set.vertices;
    if (mesh.faces.size() != patches.size()) {
        throw std::invalid_argument("the patch set has the mesh vertices of " +
                                    std::to_string(mesh.faces.size()) + " faces for " +
                                    std::to_string(patches.size()) + " patches");
    }
    build_patches(patches, mesh.vertex_count, [&](float* vertex, unsigned* index) {
        for (std::uint32_t i = 0; i < patches.size(); ++i) {
            const Patch& p = patches[i];
            const auto& v = mesh.faces[i];
            if (mesh.corner_count(i) != p.corner_count) {
                throw std::invalid_argument(
                    "face " + std::to_string(i) + " has " + std::to_string(mesh.corner_count(i)) +
                    " corners, its patch " + std::to_string(p.corner_count));
            }
            // A vertex is written once per patch that meets there, each time the same value:
            // the patches' corners are the mesh's points.
            for (int k = 0; k < p.corner_count; ++k) {
                if (v[k] >= mesh.vertex_count) {
                    throw std::invalid_argument("face " + std::to_string(i) + " names vertex " +
                                                std::to_string(v[k]) + " of " +
                                                std::to_string(mesh.vertex_count));
                }
                for (int c = 0; c < 3; ++c) vertex[3 * v[k] + c] = float(p.corner[k][c]);
            }
            add_patch_triangles(v.data(), p.is_quad(), index);
        }
    });
}

// A triangle soup's bounds are its vertices'; a patch scene's are its patches' corners, whatever
// vertices the buffers hold, so that both constructions have the same self-hit offset.
void EmbreeScene::build_patches(const std::vector<Patch>& patches, std::size_t vertex_count,
                                const std::function<void(float*, unsigned*)>& fill) {
    std::size_t triangle_count = 0;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
    for (const Patch& p : patches) {
        triangle_count += p.is_quad() ? 2 : 1;
        for (int k = 0; k < p.corner_count; ++k) {
            lo = lo.cwiseMin(p.corner[k]);
            hi = hi.cwiseMax(p.corner[k]);
        }
    }
    m_triangle_patch.reserve(triangle_count);
    build(vertex_count, triangle_count, lo, hi, fill);
}

void EmbreeScene::add_patch_triangles(const unsigned* v, bool quad, unsigned*& index) {
    for (int k : {0, 1, 2}) *index++ = v[k];
    m_triangle_patch.push(false);
    if (quad) {
        for (int k : {0, 2, 3}) *index++ = v[k];
        m_triangle_patch.push(true);
    }
}

EmbreeScene::EmbreeScene(const std::vector<Vec3>& vertices,
                         const std::vector<std::array<unsigned, 3>>& triangles)
    : m_impl(std::make_unique<Impl>()) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
    for (const Vec3& c : vertices) {
        lo = lo.cwiseMin(c);
        hi = hi.cwiseMax(c);
    }
    m_triangle_patch.reserve(triangles.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
        for (unsigned i : triangles[t]) {
            if (i >= vertices.size()) {
                throw std::invalid_argument("triangle " + std::to_string(t) + " names vertex " +
                                            std::to_string(i) + " of " +
                                            std::to_string(vertices.size()));
            }
        }
        m_triangle_patch.push(false);  // a soup's "patch" is the triangle itself
    }
    if (vertices.empty()) lo = hi = Vec3::Zero();
    const auto fill = [&](float* vertex, unsigned* index) {
        for (const Vec3& c : vertices) {
            for (int k = 0; k < 3; ++k) *vertex++ = float(c[k]);
        }
        for (const auto& t : triangles) index = std::copy(t.begin(), t.end(), index);
    };
    build(vertices.size(), triangles.size(), lo, hi, fill, /*robust=*/true);
}

void EmbreeScene::build(std::size_t vertex_count, std::size_t triangle_count, const Vec3& lo,
                        const Vec3& hi, const std::function<void(float*, unsigned*)>& fill,
                        bool robust) {
    // No "threads=N": with TBB in the process it would cap all TBB parallelism.
    m_impl->device = rtcNewDevice(nullptr);
    if (!m_impl->device) throw std::runtime_error("cannot create the Embree device");
    rtcSetDeviceErrorFunction(m_impl->device, on_embree_error, m_impl.get());
    m_offset = 1e-6 * std::max(1e-9, (hi - lo).norm());

    m_impl->scene = rtcNewScene(m_impl->device);
    rtcSetSceneBuildQuality(m_impl->scene, RTC_BUILD_QUALITY_MEDIUM);
    if (robust) rtcSetSceneFlags(m_impl->scene, RTC_SCENE_FLAG_ROBUST);
    // An empty soup is a valid scene that nothing hits; Embree rejects empty buffers.
    if (triangle_count > 0) {
        m_impl->vertices.resize(3 * vertex_count + 4);
        m_impl->indices.resize(3 * triangle_count);
        fill(m_impl->vertices.data(), m_impl->indices.data());
        RTCGeometry geom = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                   m_impl->vertices.data(), 0, 3 * sizeof(float), vertex_count);
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                   m_impl->indices.data(), 0, 3 * sizeof(unsigned), triangle_count);
        if (!m_impl->error.empty()) rtcReleaseGeometry(geom);  // before the throw below
        throw_if_failed(*m_impl, "sharing the geometry with Embree");
        rtcCommitGeometry(geom);
        rtcAttachGeometry(m_impl->scene, geom);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(m_impl->scene);
    throw_if_failed(*m_impl, "building the Embree scene");
}

EmbreeScene::~EmbreeScene() = default;

std::optional<Hit> EmbreeScene::first_hit(const Vec3& origin, const Vec3& direction) const {
    const RTCRayHit rh = intersect(m_impl->scene, origin, direction, m_offset);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return Hit{m_triangle_patch[rh.hit.primID], double(rh.ray.tfar)};
}

std::optional<TriangleHit> EmbreeScene::first_hit_triangle(const Vec3& origin,
                                                           const Vec3& direction) const {
    const RTCRayHit rh = intersect(m_impl->scene, origin, direction, m_offset);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return TriangleHit{rh.hit.primID, double(rh.hit.u), double(rh.hit.v), double(rh.ray.tfar),
                       Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z)};
}

void EmbreeScene::first_hits(const GeneratedRays& rays, std::size_t begin, std::size_t end,
                             std::span<BatchHit> hits) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(64) RTCRayHit16 rh;
    alignas(64) int valid[16];
    static_assert(kPacketRays == 16, "first_hits() makes RTCRayHit16 packets");
    // What Embree only reads, once: a query writes tfar and the hit alone.
    for (std::size_t k = 0; k < kPacketRays; ++k) {
        valid[k] = -1;
        rh.ray.tnear[k] = float(m_offset);
        rh.ray.time[k] = 0;
        rh.ray.mask[k] = ~0u;
        rh.ray.id[k] = unsigned(k);
        rh.ray.flags[k] = 0;
    }
    for (std::size_t first = begin; first < end; first += kPacketRays) {
        const std::size_t n = std::min(kPacketRays, end - first);
        for (std::size_t k = 0; k < kPacketRays; ++k) {
            // A partial packet's idle lanes repeat its first ray: every lane stays a real query
            // (some of Embree's code paths ignore the valid mask) and takes the same path.
            const std::size_t j = first + (k < n ? k : 0);
            rh.ray.org_x[k] = rays.origin[0][j];
            rh.ray.org_y[k] = rays.origin[1][j];
            rh.ray.org_z[k] = rays.origin[2][j];
            rh.ray.dir_x[k] = rays.direction[0][j];
            rh.ray.dir_y[k] = rays.direction[1][j];
            rh.ray.dir_z[k] = rays.direction[2][j];
            rh.ray.tfar[k] = kInf;
            rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect16(valid, m_impl->scene, &context, &rh);
        for (std::size_t k = 0; k < n; ++k) {
            BatchHit& h = hits[first + k];
            if (rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) {
                h.patch = BatchHit::kNoHit;
                continue;
            }
            const std::uint32_t t = rh.hit.primID[k];
            h = {m_triangle_patch[t], m_triangle_patch.second_of_quad(t), rh.ray.tfar[k],
                 rh.hit.u[k], rh.hit.v[k]};
        }
    }
}

bool EmbreeScene::visible(const Vec3& p, const Vec3& q) const {
    const Vec3 d = q - p;
    const double len = d.norm();
    if (len <= 2 * m_offset) return true;  // touching points: nothing can be between
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray;
    ray.org_x = float(p.x());
    ray.org_y = float(p.y());
    ray.org_z = float(p.z());
    ray.dir_x = float(d.x());
    ray.dir_y = float(d.y());
    ray.dir_z = float(d.z());
    ray.tnear = float(m_offset / len);
    ray.tfar = float(1 - m_offset / len);
    ray.time = 0;
    ray.mask = ~0u;
    ray.id = 0;
    ray.flags = 0;
    rtcOccluded1(m_impl->scene, &context, &ray);
    return ray.tfar >= 0;  // occluded sets tfar to -inf
}

void EmbreeScene::visible_many(std::span<const Vec3> p, std::span<const Vec3> q,
                               std::span<bool> out) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (std::size_t first = 0; first < p.size(); first += 16) {
        const std::size_t n = std::min<std::size_t>(16, p.size() - first);
        alignas(64) int valid[16];
        alignas(64) RTCRay16 ray;
        for (std::size_t k = 0; k < 16; ++k) {
            // Inactive lanes get an empty interval: some Embree paths ignore the valid mask.
            ray.tnear[k] = 1;
            ray.tfar[k] = 0;
            ray.org_x[k] = ray.org_y[k] = ray.org_z[k] = 0;
            ray.dir_x[k] = ray.dir_y[k] = 0;
            ray.dir_z[k] = 1;
            ray.time[k] = 0;
            ray.mask[k] = ~0u;
            ray.id[k] = unsigned(k);
            ray.flags[k] = 0;
            valid[k] = 0;
        }
        for (std::size_t k = 0; k < n; ++k) {
            const Vec3& a = p[first + k];
            const Vec3 d = q[first + k] - a;
            const double len = d.norm();
            out[first + k] = true;
            if (len <= 2 * m_offset) continue;  // touching points: nothing can be between
            valid[k] = -1;
            ray.org_x[k] = float(a.x());
            ray.org_y[k] = float(a.y());
            ray.org_z[k] = float(a.z());
            ray.dir_x[k] = float(d.x());
            ray.dir_y[k] = float(d.y());
            ray.dir_z[k] = float(d.z());
            ray.tnear[k] = float(m_offset / len);
            ray.tfar[k] = float(1 - m_offset / len);
        }
        rtcOccluded16(valid, m_impl->scene, &context, &ray);
        for (std::size_t k = 0; k < n; ++k) {
            if (valid[k]) out[first + k] = ray.tfar[k] >= 0;  // occluded sets tfar to -inf
        }
    }
}

}  // namespace hmcr
