// SPDX-License-Identifier: Apache-2.0
#include "common/exit_code.h"

#include "common/error.h"
#include "common/interrupt.h"
#include "common/ranks.h"

namespace hmcr {

Failure failure_of(const std::exception_ptr& e) {
    try {
        std::rethrow_exception(e);
    } catch (const InputError& x) {
        return {2, x.what()};
    } catch (const Interrupted& x) {
        // What was complete is kept (a study's cells); nothing partial is left.
        return {128 + x.signal(), std::string(x.what()) + "; no partial output left"};
    } catch (const OtherRankFailed& x) {
        return {x.exit_code(), x.what()};
    } catch (const std::exception& x) {
        return {1, std::string("internal error: ") + x.what()};
    }
}

}  // namespace hmcr
