// SPDX-License-Identifier: BSD-3-Clause
// The evaluation counter of benchmark builds (compiler.hpp); empty
// otherwise.
#include "compiler.hpp"

#ifdef PW85_COUNT_EVALUATIONS
namespace pw85::detail {
thread_local unsigned long long evaluations = 0;
unsigned long long evaluation_count() noexcept { return evaluations; }
}  // namespace pw85::detail
#endif
