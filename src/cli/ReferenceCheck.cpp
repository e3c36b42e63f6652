#include "zrender/cli/ReferenceCheck.hpp"

#include <cmath>
#include <cstdio>

#include "zrender/base/Error.hpp"
#include "zrender/io/files/OutputFile.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/images/ImageOutput.hpp"

namespace zrender {

namespace fs = std::filesystem;

namespace {

// The option names in messages, each the static text a NamedOutput holds.
const char* diffName(ReferenceKind kind) {
  switch (kind) {
    case ReferenceKind::Depth:
      return "--reference-depth's diff image";
    case ReferenceKind::Ids:
      return "--reference-ids's diff image";
    default:
      return "--reference's diff image";
  }
}

const char* jsonKey(ReferenceKind kind) {
  switch (kind) {
    case ReferenceKind::Depth:
      return "depth";
    case ReferenceKind::Ids:
      return "ids";
    default:
      return "color";
  }
}

const cv::Mat& renderedImage(ReferenceKind kind, const RenderedImages& images) {
  switch (kind) {
    case ReferenceKind::Depth:
      return images.depth;
    case ReferenceKind::Ids:
      return images.ids;
    default:
      return images.color;
  }
}

// The first reference option given, for messages about them all.
const char* firstOption(const RenderOptions& o) {
  return o.reference ? "--reference" : o.referenceDepth ? "--reference-depth" : "--reference-ids";
}

// Throws InputError unless the references can be compared with one image each of this run.
void checkReferenceOptions(const RenderOptions& o, const ViewPlan& plan) {
  const std::string option = firstOption(o);
  if (plan.multiView) {
    throw InputError("command line: " + option +
                     ": a reference is compared with a single image, not with several views "
                     "(--orbit, --turntable, the scene's views)");
  }
  if (o.frames || o.shard || o.skipExisting || o.camerasOnly) {
    throw InputError("command line: " + option +
                     ": a reference is compared with the image this run renders: not with "
                     "--frames, --shard, --skip-existing or --cameras-only");
  }
  if (o.referenceDepth && !o.depth) {
    throw InputError(
        "command line: --reference-depth needs --depth FILE, the image it is compared with");
  }
  if (o.referenceIds && !o.ids) {
    throw InputError(
        "command line: --reference-ids needs --ids FILE, the image it is compared with");
  }
  if (o.referenceTolerance && *o.referenceTolerance < 0) {
    throw InputError(
        "command line: --reference-tolerance: pixels that may differ, 0 or more; got " +
        std::to_string(*o.referenceTolerance));
  }
}

// Throws InputError when a diff image is at another output of the run, or a reference would be
// overwritten by one. References may name one file among themselves: they are only read.
void checkDistinct(const std::vector<ReferenceImage>& references, const RenderOutputs& outputs,
                   const ViewFiles& files) {
  std::vector<NamedOutput> written = files.named();
  if (outputs.cameras) written.push_back({"--cameras", *outputs.cameras});
  for (const ReferenceImage& r : references) written.push_back({diffName(r.kind), r.diff});
  checkDistinctOutputs(written);
  for (const ReferenceImage& r : references) {
    std::vector<NamedOutput> withReference = written;
    withReference.push_back({r.option, r.file});
    checkDistinctOutputs(withReference);
  }
}

}  // namespace

fs::path diffPath(const fs::path& output) {
  return output.parent_path() / (output.stem().string() + "-diff.png");
}

std::vector<ReferenceImage> readReferences(const RenderOptions& options, const ViewPlan& plan,
                                           const RenderOutputs& outputs) {
  if (!options.reference && !options.referenceDepth && !options.referenceIds) {
    if (options.referenceTolerance) {
      throw InputError(
          "command line: --reference-tolerance needs --reference, --reference-depth or "
          "--reference-ids");
    }
    return {};
  }
  checkReferenceOptions(options, plan);
  const ViewFiles files = outputs.filesOf(plan.first);
  std::vector<ReferenceImage> references;
  const auto add = [&](ReferenceKind kind, const char* option, const fs::path& file,
                       const fs::path& output) {
    ReferenceImage r;
    r.kind = kind;
    r.option = option;
    r.file = file;
    r.output = output;
    r.diff = diffPath(output);
    references.push_back(std::move(r));
  };
  if (options.reference) add(ReferenceKind::Color, "--reference", *options.reference, files.color);
  if (options.referenceDepth)
    add(ReferenceKind::Depth, "--reference-depth", *options.referenceDepth, *files.depth);
  if (options.referenceIds)
    add(ReferenceKind::Ids, "--reference-ids", *options.referenceIds, *files.ids);
  checkDistinct(references, outputs, files);

  for (ReferenceImage& r : references) {
    std::string error;
    // Color and id images are 8-bit BGR whatever their file; a depth image keeps its 16 bits
    // or its floats, so that it is compared in the units it was written in.
    r.image = r.kind == ReferenceKind::Depth ? decodeImageUnchanged(r.file, error)
                                             : decodeColorImage(r.file, error);
    if (r.image.empty()) {
      throw InputError(r.file.string() + ": " + r.option + " image " +
                       (error.empty() ? "cannot be read as an image" : error));
    }
  }
  return references;
}

void checkDiffsWritable(const std::vector<ReferenceImage>& references) {
  for (const ReferenceImage& r : references) checkWritable(r.diff);
}

std::vector<ReferenceResult> compareReferences(const std::vector<ReferenceImage>& references,
                                               const RenderedImages& images, long long tolerance,
                                               const Threads* threads) {
  std::vector<ReferenceResult> results;
  for (const ReferenceImage& r : references) {
    const cv::Mat& rendered = renderedImage(r.kind, images);
    const ImageDifference d = compareImages(rendered, r.image, images.color);
    ReferenceResult result;
    result.reference = &r;
    result.comparable = d.comparable;
    result.renderedDescription = describeImage(rendered);
    result.sameSize = rendered.size() == r.image.size();
    result.pixels = d.pixels;
    result.differingPixels = d.differingPixels;
    result.largest = d.largest;
    if (!d.marked.empty()) {
      writeImageAtomically(r.diff, d.marked, threads);
      result.diffWritten = true;
    }
    result.passed = d.comparable && d.differingPixels <= size_t(tolerance);
    results.push_back(std::move(result));
  }
  return results;
}

std::string referenceLine(const ReferenceResult& result) {
  const ReferenceImage& r = *result.reference;
  const std::string head = "zrender: reference: " + r.output.string();
  if (!result.comparable) {
    return head + " (" + result.renderedDescription + ") and " + r.file.string() + " (" +
           describeImage(r.image) + ") differ in " + (!result.sameSize ? "size" : "type") +
           "; not compared\n";
  }
  if (result.differingPixels == 0) return "";
  char largest[64];
  std::snprintf(largest, sizeof largest, "%.9g", result.largest);
  return head + " differs from " + r.file.string() + " in " +
         std::to_string(result.differingPixels) + " of " + std::to_string(result.pixels) +
         " pixels (largest channel difference " + largest + "); marked in " + r.diff.string() +
         "\n";
}

Json::Value referenceJson(const std::vector<ReferenceResult>& results, long long tolerance) {
  Json::Value all(Json::objectValue);
  for (const ReferenceResult& result : results) {
    const ReferenceImage& r = *result.reference;
    Json::Value j(Json::objectValue);
    j["file"] = r.file.string();
    j["comparable"] = result.comparable;
    j["pixels"] = result.comparable ? Json::Value(Json::UInt64(result.pixels)) : Json::Value();
    j["differing_pixels"] =
        result.comparable ? Json::Value(Json::UInt64(result.differingPixels)) : Json::Value();
    // JSON has no infinity (a NaN against a number): null, as for images not compared.
    j["largest_difference"] = result.comparable && std::isfinite(result.largest)
                                  ? Json::Value(result.largest)
                                  : Json::Value();
    j["diff"] = result.diffWritten ? Json::Value(r.diff.string()) : Json::Value();
    j["tolerance"] = Json::Int64(tolerance);
    j["passed"] = result.passed;
    all[jsonKey(r.kind)] = j;
  }
  return all;
}

}  // namespace zrender
