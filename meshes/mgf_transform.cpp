// SPDX-License-Identifier: Apache-2.0
// Parsing and composing MGF transformations (mgf_transform.h).
#include "meshes/mgf_transform.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <numbers>

#include "common/error.h"

namespace hmcr {
namespace {

double number(const std::vector<std::string_view>& args, std::size_t i, const std::string& where) {
    if (i >= args.size()) throw InputError(where, fmt::format("{} needs a number", args[i - 1]));
    double v = 0;
    const std::string_view t = args[i];
    const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc{} || ptr != t.data() + t.size() || !std::isfinite(v)) {
        throw InputError(where, fmt::format("bad number {} after {}", quote(t), args[i - 1]));
    }
    return v;
}

long long count(const std::vector<std::string_view>& args, std::size_t i,
                const std::string& where) {
    const double v = number(args, i, where);
    if (!(v >= 1 && v <= 1e9 && v == std::floor(v))) {
        throw InputError(where, fmt::format("{} needs a positive whole count, got {}", args[i - 1],
                                            quote(args[i])));
    }
    return static_cast<long long>(v);
}

MgfTransform rotation(double degrees, const Eigen::Vector3d& axis) {
    return MgfTransform(Eigen::AngleAxisd(degrees * std::numbers::pi / 180, axis));
}

MgfTransform mirror(int axis) {
    Eigen::Vector3d d = Eigen::Vector3d::Ones();
    d[axis] = -1;
    return MgfTransform(d.asDiagonal());
}

// One plain argument at args[i], applied after `t`; returns the index after it.
std::size_t apply_argument(const std::vector<std::string_view>& args, std::size_t i,
                           const std::string& where, MgfTransform& t) {
    const std::string_view flag = args[i];
    if (flag == "-t") {
        const Eigen::Vector3d d(number(args, i + 1, where), number(args, i + 2, where),
                                number(args, i + 3, where));
        t = Eigen::Translation3d(d) * t;
        return i + 4;
    }
    if (flag == "-rx" || flag == "-ry" || flag == "-rz") {
        t = rotation(number(args, i + 1, where), Eigen::Vector3d::Unit(flag[2] - 'x')) * t;
        return i + 2;
    }
    if (flag == "-s") {
        const double s = number(args, i + 1, where);
        if (s == 0) throw InputError(where, "-s 0 scales the geometry to nothing");
        t = Eigen::Scaling(s) * t;
        return i + 2;
    }
    if (flag == "-mx" || flag == "-my" || flag == "-mz") {
        t = mirror(flag[2] - 'x') * t;
        return i + 1;
    }
    throw InputError(where, fmt::format("unknown transformation argument {}", quote(flag)));
}

// t applied n times, by squaring: counts go up to 1e9.
MgfTransform power(MgfTransform t, long long n) {
    MgfTransform out = MgfTransform::Identity();
    for (; n > 0; n >>= 1, t = t * t) {
        if (n & 1) out = t * out;
    }
    return out;
}

}  // namespace

long long MgfXf::instances() const {
    long long n = 1;
    for (const MgfXfStage& s : stages) n *= s.array ? s.count : 1;
    return n;
}

MgfTransform MgfXf::instance(long long k) const {
    MgfTransform t = first;
    for (const MgfXfStage& s : stages) {
        long long times = s.count;
        if (s.array) {
            times = k % s.count;
            k /= s.count;
        }
        t = power(s.step, times) * t;
    }
    return t;
}

MgfXf parse_mgf_xf(const std::vector<std::string_view>& args, const std::string& where) {
    MgfXf xf;
    MgfTransform* current = &xf.first;
    long long instances = 1;
    for (std::size_t i = 0; i < args.size();) {
        if (args[i] == "-a" || args[i] == "-i") {
            MgfXfStage stage{args[i] == "-a", count(args, i + 1, where), MgfTransform::Identity()};
            if (stage.array && (instances *= stage.count) > 1'000'000'000) {
                throw InputError(where, "arrays of more than 1e9 instances");
            }
            xf.stages.push_back(stage);
            current = &xf.stages.back().step;
            i += 2;
        } else {
            i = apply_argument(args, i, where, *current);
        }
    }
    return xf;
}

bool mirrors(const MgfTransform& t) { return t.linear().determinant() < 0; }

}  // namespace hmcr
