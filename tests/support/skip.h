// SPDX-License-Identifier: MIT
// A test case that cannot run on this machine (a processor without the instructions it checks) says so to ctest:
// the program ends with kSkipExitCode, which ctest reports as skipped rather than passed. Programs whose tests use it
// link skip_main.cpp as their main and set SKIP_RETURN_CODE to kSkipExitCode.
#pragma once

#include <string>

namespace satviz::testing
{

/// The exit code of a run in which every test case passed or was skipped, and at least one was skipped.
constexpr int kSkipExitCode = 77;

/// Marks the running test case as not run, for `why` (printed when the program ends). Call it before any check of
/// the case and return from the case: its checks then do not run, and the program ends with kSkipExitCode if
/// nothing failed.
void SkipTestCase(const std::string& why);

} // namespace satviz::testing
