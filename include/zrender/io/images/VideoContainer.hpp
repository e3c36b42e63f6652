#pragma once

#include <filesystem>
#include <string>

namespace zrender {

// Why the video file at `path` is not a finished container, or "" when it is: an MP4 whose
// top-level boxes do not add up to the file's size or lack the index ("moov") and the frames
// ("mdat"), an AVI whose RIFF chunks do not add up to it. A writer that ran out of disk stops
// short of both, and OpenCV's video writer does not say so (docs/design.md, Outputs).
std::string videoContainerProblem(const std::filesystem::path& path);

}  // namespace zrender
