// SPDX-License-Identifier: Apache-2.0
#include "common/progress.h"

namespace hmcr {
namespace {

class NoProgress final : public Progress {
public:
    void stage(std::string_view) override {}
    void advance(double) override {}
    void note(std::string_view) override {}
};

}  // namespace

Progress& no_progress() {
    static NoProgress none;
    return none;
}

}  // namespace hmcr
