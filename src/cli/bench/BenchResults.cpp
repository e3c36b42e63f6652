#include "zrender/cli/bench/BenchResults.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <memory>

#include "zrender/base/Error.hpp"
#include "zrender/base/Median.hpp"
#include "zrender/cli/BuildInfo.hpp"
#include "zrender/io/files/FileText.hpp"

namespace zrender {

double roundedMs(double ms) {
  return std::round(ms * 1e4) / 1e4;
}

TimingSummary TimingSummary::of(std::vector<double> samples) {
  TimingSummary t;
  t.samples = std::move(samples);
  for (double& v : t.samples) v = roundedMs(v);
  if (t.samples.empty()) return t;
  t.median = zrender::median(t.samples);
  std::vector<double> deviations;
  for (double v : t.samples) deviations.push_back(std::abs(v - t.median));
  t.mad = zrender::median(deviations);
  t.min = *std::min_element(t.samples.begin(), t.samples.end());
  return t;
}

std::string BenchKey::text() const {
  return scene + "/" + algorithm + "/" + std::to_string(width) + "x" + std::to_string(height) +
         "/msaa" + std::to_string(msaa) + "/" + shading;
}

bool BenchKey::operator==(const BenchKey& o) const {
  return scene == o.scene && algorithm == o.algorithm && shading == o.shading && width == o.width &&
         height == o.height && msaa == o.msaa;
}

namespace {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(colon + 1);
    name.erase(0, name.find_first_not_of(' '));
    return name;
  }
  return "unknown";
}

std::string utcNow() {
  char buf[32];
  const std::time_t t = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

Json::Value timingToJson(const TimingSummary& t) {
  Json::Value j(Json::objectValue);
  j["median"] = t.median;
  j["mad"] = t.mad;
  j["min"] = t.min;
  Json::Value samples(Json::arrayValue);
  for (double v : t.samples) samples.append(v);
  j["samples"] = samples;
  return j;
}

// Reads what benchRunToJson writes; `where` is the file and the key path so far.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_ + ": " + key + ": " + what);
  }
  const Json::Value& member(const Json::Value& o, const std::string& key,
                            const std::string& name) const {
    if (!o.isObject()) fail(key, "expected an object");
    if (!o.isMember(name)) fail(key + "." + name, "missing");
    return o[name];
  }
  std::string text(const Json::Value& o, const std::string& key, const std::string& name) const {
    const Json::Value& v = member(o, key, name);
    if (!v.isString()) fail(key + "." + name, "expected a string");
    return v.asString();
  }
  double number(const Json::Value& o, const std::string& key, const std::string& name) const {
    const Json::Value& v = member(o, key, name);
    if (!v.isNumeric() || !std::isfinite(v.asDouble()) || v.asDouble() < 0)
      fail(key + "." + name, "expected a number of at least 0");
    return v.asDouble();
  }
  int integer(const Json::Value& o, const std::string& key, const std::string& name, int lo,
              int hi) const {
    const Json::Value& v = member(o, key, name);
    if (!v.isInt() || v.asInt() < lo || v.asInt() > hi)
      fail(key + "." + name,
           "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
    return v.asInt();
  }
  bool boolean(const Json::Value& o, const std::string& key, const std::string& name) const {
    const Json::Value& v = member(o, key, name);
    if (!v.isBool()) fail(key + "." + name, "expected true or false");
    return v.asBool();
  }
  TimingSummary timing(const Json::Value& o, const std::string& key,
                       const std::string& name) const {
    const std::string at = key + "." + name;
    const Json::Value& v = member(o, key, name);
    const Json::Value& samples = member(v, at, "samples");
    if (!samples.isArray() || samples.empty()) fail(at + ".samples", "expected a list of times");
    std::vector<double> values;
    for (Json::ArrayIndex i = 0; i < samples.size(); ++i) {
      if (!samples[i].isNumeric() || !std::isfinite(samples[i].asDouble()) ||
          samples[i].asDouble() < 0)
        fail(at + ".samples[" + std::to_string(i) + "]", "expected a time in ms");
      values.push_back(samples[i].asDouble());
    }
    // The summary is recomputed from the samples, so an edited file cannot disagree with them.
    return TimingSummary::of(values);
  }

 private:
  std::string file_;
};

// A key's fields in a cell or picture object; a picture's algorithm is always the z-buffer's,
// and not written.
void keyToJson(const BenchKey& key, bool withAlgorithm, Json::Value& out) {
  out["scene"] = key.scene;
  if (withAlgorithm) out["algorithm"] = key.algorithm;
  out["width"] = key.width;
  out["height"] = key.height;
  out["msaa"] = key.msaa;
  out["shading"] = key.shading;
}

BenchKey keyFromJson(const Reader& r, const Json::Value& v, const std::string& at,
                     bool withAlgorithm) {
  BenchKey key;
  key.scene = r.text(v, at, "scene");
  key.algorithm = withAlgorithm ? r.text(v, at, "algorithm") : "zbuffer";
  key.width = r.integer(v, at, "width", 1, 16384);
  key.height = r.integer(v, at, "height", 1, 16384);
  key.msaa = r.integer(v, at, "msaa", 1, 64);
  key.shading = r.text(v, at, "shading");
  return key;
}

}  // namespace

BenchRun BenchRun::describingThisProcess() {
  const BuildInfo build = buildInfo();
  BenchRun run;
  run.version = build.version;
  run.commit = build.commit;
  run.compiler = build.compiler;
  run.buildType = build.buildType;
  run.cpu = cpuModel();
  run.cores = int(sysconf(_SC_NPROCESSORS_ONLN));
  run.date = utcNow();
  return run;
}

Json::Value benchRunToJson(const BenchRun& run) {
  Json::Value j(Json::objectValue);
  j["schema"] = BenchRun::kSchema;
  Json::Value zr(Json::objectValue);
  zr["version"] = run.version;
  zr["commit"] = run.commit.empty() ? Json::Value(Json::nullValue) : Json::Value(run.commit);
  zr["compiler"] = run.compiler;
  zr["build_type"] = run.buildType;
  j["zrender"] = zr;
  Json::Value machine(Json::objectValue);
  machine["cpu"] = run.cpu;
  machine["cores"] = run.cores;
  j["machine"] = machine;
  j["threads"] = run.threads;
  j["date"] = run.date;
  Json::Value command(Json::arrayValue);
  for (const std::string& a : run.command) command.append(a);
  j["command"] = command;
  j["repeat"] = run.repeat;
  j["warmup"] = run.warmup;
  Json::Value cells(Json::arrayValue);
  for (const BenchCell& c : run.cells) {
    Json::Value cell(Json::objectValue);
    keyToJson(c.key, true, cell);
    cell["faces"] = Json::UInt64(c.faces);
    cell["prepare_ms"] = c.prepareMs;
    cell["frame_ms"] = timingToJson(c.frame);
    cell["transform_ms"] = timingToJson(c.transform);
    cell["visibility_ms"] = timingToJson(c.visibility);
    cell["shade_ms"] = timingToJson(c.shade);
    cell["raster_ms"] = timingToJson(c.raster);
    cell["probe_ms"] = timingToJson(c.probe);
    if (c.oneThreadFrame) cell["one_thread_frame_ms"] = timingToJson(*c.oneThreadFrame);
    cell["stats"] = c.stats.isObject() ? c.stats : Json::Value(Json::objectValue);
    cell["identical"] = c.identical;
    cells.append(cell);
  }
  j["cells"] = cells;
  Json::Value pictures(Json::arrayValue);
  for (const BenchPicture& p : run.pictures) {
    Json::Value picture(Json::objectValue);
    keyToJson(p.key, false, picture);
    picture["image"] = p.imageUri;
    pictures.append(picture);
  }
  j["pictures"] = pictures;
  return j;
}

std::string benchRunText(const BenchRun& run) {
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "  ";
  // Microseconds: the samples keep what the clock measured, to the resolution that matters.
  builder["precision"] = 4;
  builder["precisionType"] = "decimal";
  builder["emitUTF8"] = true;
  return Json::writeString(builder, benchRunToJson(run)) + "\n";
}

BenchRun benchRunFromJson(const Json::Value& j, const std::string& where) {
  const Reader r(where);
  if (!j.isObject()) r.fail("(top)", "expected an object, the results of zrender bench --json");
  const int schema = r.integer(j, "(top)", "schema", 0, 1000000);
  if (schema != BenchRun::kSchema)
    r.fail("schema", "version " + std::to_string(schema) + " is not the one this zrender reads (" +
                         std::to_string(BenchRun::kSchema) + ")");
  BenchRun run;
  const Json::Value& zr = r.member(j, "(top)", "zrender");
  run.version = r.text(zr, "zrender", "version");
  const Json::Value& commit = r.member(zr, "zrender", "commit");
  if (!commit.isNull() && !commit.isString()) r.fail("zrender.commit", "expected a string or null");
  run.commit = commit.isString() ? commit.asString() : "";
  run.compiler = r.text(zr, "zrender", "compiler");
  run.buildType = r.text(zr, "zrender", "build_type");
  const Json::Value& machine = r.member(j, "(top)", "machine");
  run.cpu = r.text(machine, "machine", "cpu");
  run.cores = r.integer(machine, "machine", "cores", 1, 1 << 20);
  run.threads = r.integer(j, "(top)", "threads", 1, 1 << 20);
  run.date = r.text(j, "(top)", "date");
  const Json::Value& command = r.member(j, "(top)", "command");
  if (!command.isArray()) r.fail("command", "expected a list of strings");
  for (const Json::Value& a : command) {
    if (!a.isString()) r.fail("command", "expected a list of strings");
    run.command.push_back(a.asString());
  }
  run.repeat = r.integer(j, "(top)", "repeat", 1, 100000);
  run.warmup = r.integer(j, "(top)", "warmup", 0, 100000);
  const Json::Value& cells = r.member(j, "(top)", "cells");
  if (!cells.isArray()) r.fail("cells", "expected a list");
  for (Json::ArrayIndex i = 0; i < cells.size(); ++i) {
    const std::string at = "cells[" + std::to_string(i) + "]";
    const Json::Value& c = cells[i];
    BenchCell cell;
    cell.key = keyFromJson(r, c, at, true);
    cell.faces = uint64_t(r.number(c, at, "faces"));
    cell.prepareMs = roundedMs(r.number(c, at, "prepare_ms"));
    cell.frame = r.timing(c, at, "frame_ms");
    cell.transform = r.timing(c, at, "transform_ms");
    cell.visibility = r.timing(c, at, "visibility_ms");
    cell.shade = r.timing(c, at, "shade_ms");
    cell.raster = r.timing(c, at, "raster_ms");
    cell.probe = r.timing(c, at, "probe_ms");
    if (cell.probe.samples.size() != cell.frame.samples.size())
      r.fail(at + ".probe_ms.samples", "expected one per frame, as frame_ms.samples");
    if (c.isMember("one_thread_frame_ms"))
      cell.oneThreadFrame = r.timing(c, at, "one_thread_frame_ms");
    cell.stats = r.member(c, at, "stats");
    if (!cell.stats.isObject()) r.fail(at + ".stats", "expected an object");
    cell.identical = r.boolean(c, at, "identical");
    for (const BenchCell& other : run.cells)
      if (other.key == cell.key) r.fail(at, "a second cell " + cell.key.text());
    run.cells.push_back(cell);
  }
  if (j.isMember("pictures")) {
    const Json::Value& pictures = j["pictures"];
    if (!pictures.isArray()) r.fail("pictures", "expected a list");
    for (Json::ArrayIndex i = 0; i < pictures.size(); ++i) {
      const std::string at = "pictures[" + std::to_string(i) + "]";
      const Json::Value& p = pictures[i];
      BenchPicture picture;
      picture.key = keyFromJson(r, p, at, false);
      picture.imageUri = r.text(p, at, "image");
      if (picture.imageUri.rfind("data:image/", 0) != 0)
        r.fail(at + ".image", "expected a data: URI of an image");
      run.pictures.push_back(picture);
    }
  }
  return run;
}

BenchRun readBenchRun(const std::filesystem::path& path) {
  const FileText file(path.string(), size_t(256) << 20);
  const std::string_view text = file.text();
  Json::CharReaderBuilder builder;
  Json::CharReaderBuilder::strictMode(&builder.settings_);
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  Json::Value json;
  std::string errors;
  if (!reader->parse(text.data(), text.data() + text.size(), &json, &errors))
    throw InputError(path.string() + ": not a JSON file: " + messageLine(errors));
  return benchRunFromJson(json, path.string());
}

}  // namespace zrender
