// SPDX-License-Identifier: MIT
// satviz render: PNG files written atomically (a temporary file renamed over the target), so that a failed or
// interrupted write never leaves a truncated image or destroys the previous one.
#pragma once

#include <string>
#include <vector>

namespace satviz
{

/// Encodes width x height RGB pixels (rows top to bottom, or bottom to top when `bottomUp`) as a PNG and writes
/// it to `path` atomically. Returns false with a one-line error naming the file.
bool WritePngFile(const std::string& path, const std::vector<unsigned char>& rgb, int width, int height, bool bottomUp,
                  std::string& error);

/// Encodes RGB pixels as PNG bytes.
std::vector<unsigned char> EncodePng(const std::vector<unsigned char>& rgb, int width, int height, bool bottomUp);

} // namespace satviz
