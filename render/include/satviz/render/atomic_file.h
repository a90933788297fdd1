// SPDX-License-Identifier: MIT
// satviz render: files written atomically (a temporary file beside the target, renamed over it), so that a failed
// or interrupted write never leaves a truncated figure or destroys the previous one.
#pragma once

#include <string>
#include <string_view>

namespace satviz
{

/// Writes `bytes` to `path` atomically. Returns false with a one-line error naming the file.
bool WriteFileAtomically(const std::string& path, std::string_view bytes, std::string& error);

} // namespace satviz
