#pragma once

// A render compared with reference images: --reference (the color image), --reference-depth,
// --reference-ids and --reference-tolerance (docs/design.md, Reference images). The references
// are read before any work; after the frame, each is compared with the image the run wrote,
// and where pixels differ a diff image marks them.

#include <filesystem>
#include <string>
#include <vector>

#include <json/json.h>
#include <opencv2/core/mat.hpp>

#include "zrender/cli/RenderCommand.hpp"
#include "zrender/cli/RenderOutputs.hpp"
#include "zrender/cli/ViewPlan.hpp"
#include "zrender/io/images/ImageDifference.hpp"

namespace zrender {

class Threads;

// Which image of a view a reference is compared with.
enum class ReferenceKind { Color, Depth, Ids };

// One reference, read.
struct ReferenceImage {
  ReferenceKind kind = ReferenceKind::Color;
  const char* option = "";       // "--reference", "--reference-depth", "--reference-ids"
  std::filesystem::path file;    // the reference (REF)
  std::filesystem::path output;  // the file of the image it is compared with (OUT)
  std::filesystem::path diff;    // where the differing pixels are marked (diffPath(output))
  cv::Mat image;                 // REF decoded: 8-bit BGR, or a depth image as its file holds it
};

// `output` with "-diff.png" in place of its extension: out.png -> out-diff.png,
// d.tif -> d-diff.png.
std::filesystem::path diffPath(const std::filesystem::path& output);

// The references `options` names, read, for the views of `plan` written to `outputs`. Throws
// InputError for a reference with several views or a part of them (--frames, --shard,
// --skip-existing, --cameras-only), --reference-depth without --depth (--reference-ids without
// --ids), --reference-tolerance without a reference, a diff image or a reference at one of the
// run's outputs, or a reference that cannot be read. Called before the loading: bad input
// writes nothing.
std::vector<ReferenceImage> readReferences(const RenderOptions& options, const ViewPlan& plan,
                                           const RenderOutputs& outputs);

// Throws InputError unless every diff image could be written (checkWritable), before the frame.
void checkDiffsWritable(const std::vector<ReferenceImage>& references);

// The images of a view as written (the depth and ids images empty when not written).
struct RenderedImages {
  cv::Mat color, depth, ids;
};

// A reference compared with its image.
struct ReferenceResult {
  const ReferenceImage* reference = nullptr;
  bool comparable = false;  // same size and type
  bool sameSize = false;
  std::string renderedDescription;  // describeImage of the rendered image, for a mismatch
  size_t pixels = 0, differingPixels = 0;
  double largest = 0.0;      // ImageDifference::largest
  bool diffWritten = false;  // some pixel differs: the diff image is written
  bool passed = false;       // comparable, and at most the tolerance's pixels differ
};

// Compares each reference with its image of `images` and writes the diff image of each that
// differs (writeImageAtomically, by `threads`), whether or not within `tolerance` pixels.
std::vector<ReferenceResult> compareReferences(const std::vector<ReferenceImage>& references,
                                               const RenderedImages& images, long long tolerance,
                                               const Threads* threads);

// What a result prints on stderr, one line with its newline, "zrender: reference: OUT differs
// from REF in N of M pixels (...); marked in DIFF" or the sizes and types of a mismatch; ""
// when the images are equal.
std::string referenceLine(const ReferenceResult& result);

// The "reference" object of --json: per kind ("color", "depth", "ids") the reference file, the
// pixels compared and those that differ, the largest difference, the diff file or null, the
// tolerance and whether it passed (docs/design.md, Timings and JSON).
Json::Value referenceJson(const std::vector<ReferenceResult>& results, long long tolerance);

}  // namespace zrender
