// SPDX-License-Identifier: Apache-2.0
// MGF transformations (the arguments of `xf` and `i`): -t, -rx, -ry, -rz, -s, -mx, -my, -mz,
// and the repeats -i N (apply what follows N times) and arrays -a N (N instances, the k-th
// moved by what follows k times). Each argument acts on the geometry as the previous ones left
// it, and an enclosed context's transformation acts before the enclosing one's.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <string_view>
#include <vector>

namespace hmcr {

// Rigid motions with uniform scale and mirrors.
using MgfTransform = Eigen::Affine3d;

// The arguments split at -a and -i: first the plain ones, then one stage per -a or -i, each
// with the transformation of its arguments (up to the next -a or -i).
struct MgfXfStage {
    bool array = false;  // -a: `count` instances; -i: `step` applied `count` times, once
    long long count = 1;
    MgfTransform step = MgfTransform::Identity();
};

struct MgfXf {
    MgfTransform first = MgfTransform::Identity();
    std::vector<MgfXfStage> stages;

    // Number of instances: the product of the array counts.
    long long instances() const;
    // The transformation of instance k (0 <= k < instances()): the first array varies fastest.
    MgfTransform instance(long long k) const;
};

// Parses xf arguments. Throws InputError(where, ...) on an unknown flag, a missing or bad number,
// a zero scale, or a count that is not a positive integer.
MgfXf parse_mgf_xf(const std::vector<std::string_view>& args, const std::string& where);

// True when the transformation mirrors (its linear part has a negative determinant): polygon
// corners must then be reversed to keep facing the same way relative to the geometry.
bool mirrors(const MgfTransform& t);

}  // namespace hmcr
