#include "zrender/io/Settings.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <string_view>
#include <system_error>
#include <vector>

#include <json/json.h>

#include "zrender/scene/Transforms.hpp"

namespace zrender {

namespace {

namespace fs = std::filesystem;

constexpr long long kMaxInstances = 1000000;
// A settings file is a few kilobytes; the cap keeps `--settings /dev/zero` from hanging.
constexpr std::size_t kMaxSettingsBytes = 64u << 20;
// settings.json nests at most three levels (scene, grid, array); the cap turns a pathological
// "[[[[..." into a clean error instead of deep recursion.
constexpr int kJsonStackLimit = 64;
// Longest excerpt of the offending value quoted after "got".
constexpr std::size_t kMaxExcerpt = 60;

// Keys of a scene and of its grid (SPEC §3); any other key is warned about and ignored.
const std::set<std::string> kSceneKeys{"path",  "width",   "height",     "eye",  "target",  "up",
                                       "angle", "axis",    "project",    "fit",  "shading", "msaa",
                                       "cull",  "texture", "background", "grid", "bench"};
const std::set<std::string> kGridKeys{"count", "spacing"};

// Escapes control characters so that a message stays on one line whatever the file holds.
std::string printable(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

// Shortest text that reads back as the same double ("0.1", not "0.10000000000000001").
std::string formatNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  // Whole numbers as written ("180", not "1.8e+02"); below 1e15 every one is exact.
  if (v == std::floor(v) && std::abs(v) < 1e15) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string formatVec(const cv::Vec3d& v) {
  return "[" + formatNumber(v[0]) + ", " + formatNumber(v[1]) + ", " + formatNumber(v[2]) + "]";
}

bool isFiniteVec(const cv::Vec3d& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// A direction must survive v / |v|: a zero length, or one that under- or overflows, does not.
bool isUsableDirection(const cv::Vec3d& v) {
  const double length = cv::norm(v);
  return length > 0.0 && std::isfinite(length);
}

// jsoncpp reports "* Line 3, Column 5\n  Syntax error: ...\n* Line ...": keep the first error and
// make it one line: "line 3, column 5: Syntax error: ...".
std::string firstJsonError(const std::string& errs) {
  std::istringstream in(errs);
  std::string line, location, message;
  while (std::getline(in, line)) {
    if (line.rfind("* ", 0) == 0) {
      if (!location.empty()) break;  // the start of the second error
      location = line.substr(2);     // "Line 3, Column 5"
      for (auto& c : location) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else {
      const auto begin = line.find_first_not_of(' ');
      if (begin == std::string::npos) continue;
      if (!message.empty()) message += ' ';
      message += line.substr(begin);
    }
  }
  if (location.empty() && message.empty()) return "unknown error";
  if (location.empty()) return printable(message);
  return printable(location + ": " + message);
}

std::string describeScene(const fs::path& file, const std::string& scene) {
  return file.string() + ": scene '" + printable(scene) + "'";
}

// The offending value as written in the file, on one line and shortened.
std::string excerpt(std::string_view text, const Json::Value& v) {
  const auto start = static_cast<std::size_t>(v.getOffsetStart());
  const auto limit = static_cast<std::size_t>(v.getOffsetLimit());
  std::string raw;
  if (start < limit && limit <= text.size()) {
    raw = std::string(text.substr(start, limit - start));
  } else {
    Json::StreamWriterBuilder writer;
    writer["indentation"] = "";
    raw = Json::writeString(writer, v);
  }
  std::string flat;
  bool space = false;
  for (char c : raw) {
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') {
      space = true;
      continue;
    }
    if (space && !flat.empty()) flat += ' ';
    space = false;
    flat += c;
  }
  if (flat.size() > kMaxExcerpt) {
    std::size_t cut = kMaxExcerpt;
    // Do not split a UTF-8 sequence: back up over continuation bytes.
    while (cut > 0 && (static_cast<unsigned char>(flat[cut]) & 0xC0) == 0x80) --cut;
    while (cut > 0 && flat[cut - 1] == ' ') --cut;
    flat.resize(cut);
    flat += "...";
  }
  return printable(flat);
}

[[noreturn]] void failKey(const std::string& where, const std::string& key,
                          const std::string& what) {
  throw InputError(where + ": key '" + key + "': " + what);
}

// Checks shared by parsing and validateScene, so a value set on the command line gets the same
// message as one from the file.
void checkSize(const std::string& where, const std::string& key, int value) {
  if (value < 1 || value > kMaxImageSize) {
    failKey(where, key,
            "expected an integer from 1 to " + std::to_string(kMaxImageSize) + ", got " +
                std::to_string(value));
  }
}

// `nearBeforeFar`: whether far > near is checked here (not when fit supplies one of them, from
// the model: makeCamera checks it then).
void checkProjection(const std::string& where, double fovy, double aspect, double near, double far,
                     bool nearBeforeFar = true) {
  if (!std::isfinite(fovy) || !std::isfinite(aspect) || !std::isfinite(near) ||
      !std::isfinite(far)) {
    failKey(where, "project",
            "expected 4 finite numbers [fovy, aspect, near, far], got [" + formatNumber(fovy) +
                ", " + formatNumber(aspect) + ", " + formatNumber(near) + ", " + formatNumber(far) +
                "]");
  }
  if (!(fovy > 0.0 && fovy < 180.0)) {
    failKey(where, "project",
            "fovy must be greater than 0 and less than 180 degrees, got " + formatNumber(fovy));
  }
  if (!(near > 0.0)) {
    failKey(where, "project", "near must be greater than 0, got " + formatNumber(near));
  }
  if (nearBeforeFar && !(far > near)) {
    failKey(where, "project",
            "far must be greater than near, got near " + formatNumber(near) + " and far " +
                formatNumber(far));
  }
}

void checkMsaa(const std::string& where, int msaa) {
  if (msaa != 1 && msaa != 4)
    failKey(where, "msaa", "expected 1 or 4, got " + std::to_string(msaa));
}

void checkFinite(const std::string& where, const std::string& key, const cv::Vec3d& v) {
  if (!isFiniteVec(v)) failKey(where, key, "expected 3 finite numbers, got " + formatVec(v));
}

void checkDirection(const std::string& where, const std::string& key, const cv::Vec3d& v) {
  checkFinite(where, key, v);
  if (!isUsableDirection(v)) {
    failKey(where, key, "must have a non-zero length, got " + formatVec(v));
  }
}

void checkGridCount(const std::string& where, const std::array<int, 3>& count) {
  for (int n : count) {
    if (n < 1 || n > kMaxInstances) {
      failKey(where, "grid.count",
              "expected 3 integers from 1 to " + std::to_string(kMaxInstances) + ", got [" +
                  std::to_string(count[0]) + ", " + std::to_string(count[1]) + ", " +
                  std::to_string(count[2]) + "]");
    }
  }
  // Each factor is at most 1e6, so the product fits in 64 bits.
  const long long total = static_cast<long long>(count[0]) * count[1] * count[2];
  if (total > kMaxInstances) {
    failKey(where, "grid.count",
            "at most " + std::to_string(kMaxInstances) + " instances in all, got " +
                std::to_string(count[0]) + " x " + std::to_string(count[1]) + " x " +
                std::to_string(count[2]) + " = " + std::to_string(total));
  }
}

// Reads the keys of one scene object; every message names the file, the scene and the key.
class SceneReader {
 public:
  SceneReader(std::string_view text, const fs::path& file, std::string where)
      : text_(text), folder_(file.parent_path()), where_(std::move(where)) {}

  SceneSettings read(const std::string& name, const Json::Value& object, Warnings& warnings) const;

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    failKey(where_, key, what);
  }

  std::string got(const Json::Value& v) const { return ", got " + excerpt(text_, v); }

  static bool integerIn(const Json::Value& v, long long lo, long long hi, long long& out) {
    if (!v.isNumeric()) return false;  // excludes booleans and null
    const double d = v.asDouble();
    if (!std::isfinite(d) || d != std::floor(d) || d < lo || d > hi) return false;
    out = static_cast<long long>(d);
    return true;
  }

  static bool finiteNumber(const Json::Value& v, double& out) {
    if (!v.isNumeric()) return false;
    out = v.asDouble();
    return std::isfinite(out);
  }

  int readSize(const Json::Value& v, const std::string& key) const {
    long long n = 0;
    if (!integerIn(v, 1, kMaxImageSize, n)) {
      fail(key, "expected an integer from 1 to " + std::to_string(kMaxImageSize) + got(v));
    }
    return static_cast<int>(n);
  }

  double readNumber(const Json::Value& v, const std::string& key) const {
    double d = 0.0;
    if (!finiteNumber(v, d)) fail(key, "expected a finite number" + got(v));
    return d;
  }

  bool readBool(const Json::Value& v, const std::string& key) const {
    if (!v.isBool()) fail(key, "expected true or false" + got(v));
    return v.asBool();
  }

  cv::Vec3d readVec3(const Json::Value& v, const std::string& key) const {
    cv::Vec3d out;
    bool ok = v.isArray() && v.size() == 3;
    for (Json::ArrayIndex i = 0; ok && i < 3; ++i) ok = finiteNumber(v[i], out[i]);
    if (!ok) fail(key, "expected an array of 3 finite numbers" + got(v));
    return out;
  }

  fs::path readPath(const Json::Value& v, const std::string& key) const {
    if (!v.isString()) fail(key, "expected a string (a file path)" + got(v));
    const std::string s = v.asString();
    if (s.empty()) fail(key, "expected a non-empty file path");
    if (s.find('\0') != std::string::npos) fail(key, "a file path cannot contain NUL" + got(v));
    // Relative to the settings file's folder; an absolute path replaces the folder.
    return folder_ / fs::path(s);
  }

  void readProject(const Json::Value& v, SceneSettings& scene) const {
    double values[4] = {};
    bool ok = v.isArray() && v.size() == 4;
    for (Json::ArrayIndex i = 0; ok && i < 4; ++i) ok = finiteNumber(v[i], values[i]);
    if (!ok) fail("project", "expected [fovy, aspect, near, far] (4 finite numbers)" + got(v));
    scene.fovy = values[0];
    scene.aspect = values[1];
    // The seed stores near and far as negative z distances; only the distance matters.
    scene.near = std::abs(values[2]);
    scene.far = std::abs(values[3]);
    checkProjection(where_, scene.fovy, scene.aspect, scene.near, scene.far);
  }

  ShadingMode readShading(const Json::Value& v) const {
    std::string names;
    for (const auto& name : shadingModeNames()) names += (names.empty() ? "" : ", ") + name;
    if (!v.isString()) fail("shading", "expected one of " + names + got(v));
    const auto mode = parseShadingMode(v.asString());
    if (!mode) fail("shading", "expected one of " + names + got(v));
    return *mode;
  }

  int readMsaa(const Json::Value& v) const {
    long long n = 0;
    if (!integerIn(v, 1, 4, n) || (n != 1 && n != 4)) fail("msaa", "expected 1 or 4" + got(v));
    return static_cast<int>(n);
  }

  std::array<int, 3> readBackground(const Json::Value& v) const {
    std::array<int, 3> rgb{};
    bool ok = v.isArray() && v.size() == 3;
    for (Json::ArrayIndex i = 0; ok && i < 3; ++i) {
      long long c = 0;
      ok = integerIn(v[i], 0, 255, c);
      rgb[i] = static_cast<int>(c);
    }
    if (!ok) fail("background", "expected an array of 3 integers from 0 to 255" + got(v));
    return rgb;
  }

  Grid readGrid(const Json::Value& v, Warnings& warnings) const {
    if (!v.isObject()) {
      fail("grid",
           "expected an object {\"count\": [nx, ny, nz], \"spacing\": [sx, sy, sz]}" + got(v));
    }
    for (const auto& key : v.getMemberNames()) {
      if (!kGridKeys.count(key)) {
        warnings.push_back(where_ + ": unknown key 'grid." + printable(key) + "' (ignored)");
      }
    }
    // Absent members keep Grid's defaults: one instance per axis, no spacing.
    Grid grid;
    if (v.isMember("count")) {
      const Json::Value& count = v["count"];
      bool ok = count.isArray() && count.size() == 3;
      for (Json::ArrayIndex i = 0; ok && i < 3; ++i) {
        long long n = 0;
        ok = integerIn(count[i], 1, kMaxInstances, n);
        grid.count[i] = static_cast<int>(n);
      }
      if (!ok) {
        fail("grid.count", "expected an array of 3 integers from 1 to " +
                               std::to_string(kMaxInstances) + got(count));
      }
      checkGridCount(where_, grid.count);
    }
    if (v.isMember("spacing")) grid.spacing = readVec3(v["spacing"], "grid.spacing");
    return grid;
  }

  std::string_view text_;  // the parsed JSON, which value offsets index
  fs::path folder_;
  std::string where_;
};

SceneSettings SceneReader::read(const std::string& name, const Json::Value& object,
                                Warnings& warnings) const {
  for (const auto& key : object.getMemberNames()) {
    if (!kSceneKeys.count(key)) {
      warnings.push_back(where_ + ": unknown key '" + printable(key) + "' (ignored)");
    }
  }
  SceneSettings scene;
  scene.name = name;
  if (!object.isMember("path")) fail("path", "missing");
  scene.modelPath = readPath(object["path"], "path");
  if (object.isMember("width")) scene.width = readSize(object["width"], "width");
  if (object.isMember("height")) scene.height = readSize(object["height"], "height");
  if (object.isMember("eye")) scene.eye = readVec3(object["eye"], "eye");
  if (object.isMember("target")) scene.target = readVec3(object["target"], "target");
  if (object.isMember("up")) {
    scene.up = readVec3(object["up"], "up");
    checkDirection(where_, "up", scene.up);
  }
  if (object.isMember("angle")) scene.angle = readNumber(object["angle"], "angle");
  if (object.isMember("axis")) {
    scene.axis = readVec3(object["axis"], "axis");
    checkDirection(where_, "axis", scene.axis);
  }
  if (object.isMember("project")) readProject(object["project"], scene);
  if (object.isMember("fit")) scene.fit = readBool(object["fit"], "fit");
  if (object.isMember("shading")) scene.shading = readShading(object["shading"]);
  if (object.isMember("msaa")) scene.msaa = readMsaa(object["msaa"]);
  if (object.isMember("cull")) scene.cull = readBool(object["cull"], "cull");
  if (object.isMember("texture")) scene.texture = readPath(object["texture"], "texture");
  if (object.isMember("background")) scene.background = readBackground(object["background"]);
  if (object.isMember("grid")) scene.grid = readGrid(object["grid"], warnings);
  if (object.isMember("bench")) scene.bench = readBool(object["bench"], "bench");
  return scene;
}

}  // namespace

SettingsFile parseSettings(const std::string& text, const fs::path& path, Warnings& warnings) {
  const std::string file = path.string();
  // Strict JSON (no trailing commas, single quotes, NaN or Infinity; nothing after the top-level
  // value; duplicate keys rejected, since a silently ignored duplicate scene or key is a trap),
  // except that comments are allowed: they cost nothing and let users annotate their scenes.
  Json::CharReaderBuilder builder;
  Json::CharReaderBuilder::strictMode(&builder.settings_);
  builder["allowComments"] = true;
  builder["collectComments"] = false;
  builder["stackLimit"] = kJsonStackLimit;
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());

  // Skip a UTF-8 byte order mark here rather than in jsoncpp, whose value offsets would then
  // count from after it while its line and column numbers do not.
  std::string_view json = text;
  if (json.substr(0, 3) == "\xEF\xBB\xBF") json.remove_prefix(3);
  Json::Value root;
  std::string errors;
  bool ok = false;
  try {
    ok = reader->parse(json.data(), json.data() + json.size(), &root, &errors);
  } catch (const Json::Exception&) {
    // jsoncpp throws rather than reports when the stack limit is exceeded.
    throw InputError(file + ": bad JSON: nested deeper than " + std::to_string(kJsonStackLimit) +
                     " levels");
  }
  if (!ok) throw InputError(file + ": bad JSON: " + firstJsonError(errors));
  if (!root.isObject()) {
    throw InputError(file + ": expected a JSON object of scenes at the top level, got " +
                     (root.isArray() ? "an array" : "another value"));
  }

  SettingsFile settings;
  settings.path = path;
  for (const auto& name : root.getMemberNames()) {
    const std::string sceneWhere = describeScene(path, name);
    const Json::Value& object = root[name];
    if (!object.isObject()) {
      throw InputError(sceneWhere + ": expected an object of scene keys, got " +
                       excerpt(json, object));
    }
    const SceneReader sceneReader(json, path, sceneWhere);
    settings.scenes.emplace(name, sceneReader.read(name, object, warnings));
  }
  return settings;
}

SettingsFile loadSettings(const fs::path& path, Warnings& warnings) {
  const std::string file = path.string();
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(file + ": cannot open file (it is a folder)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(file + ": cannot open file");
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSettingsBytes) {
      throw InputError(file + ": file too large for a settings file (over " +
                       std::to_string(kMaxSettingsBytes >> 20) + " MiB)");
    }
  }
  if (in.bad()) throw InputError(file + ": cannot read file");
  return parseSettings(text, path, warnings);
}

SceneSettings defaultSceneForModel(const fs::path& modelPath) {
  SceneSettings scene;
  scene.name = modelPath.stem().string();
  scene.modelPath = modelPath;
  scene.fit = true;
  return scene;
}

void validateScene(const SceneSettings& scene, const std::string& sceneWhere,
                   const KeyOrigins& origins) {
  // The prefix for one key: the scene, and the options that set what that key's rule checks.
  const auto at = [&](const std::string& key) {
    const auto it = origins.find(key);
    return it == origins.end() ? sceneWhere : sceneWhere + " with " + it->second;
  };
  checkSize(at("width"), "width", scene.width);
  checkSize(at("height"), "height", scene.height);
  const FitKeeps& keep = scene.fitKeeps;
  const bool fitNear = scene.fit && !keep.near, fitFar = scene.fit && !keep.far;
  // With fit, a near or far of the file is checked even though fit replaces it; one the user
  // gave beside one fit supplies is checked against it in makeCamera.
  checkProjection(at("project"), scene.fovy, scene.aspect, scene.near, scene.far,
                  !scene.fit || keep.near == keep.far);
  {
    // Extreme finite values can still overflow the projection (2 far near / (near - far) once
    // far near passes 1e308, 1 / tan of a denormal fovy), and a non-finite camera would draw
    // nothing. fit replaces near and far by the ones that frame the model; fovy and aspect
    // are checked with those of a unit model (a bigger model's own overflow is makeCamera's to
    // report, naming the model).
    const double aspect =
        scene.aspect > 0.0 ? scene.aspect : double(scene.width) / double(scene.height);
    const FitView unit = fitView(1.0, scene.fovy, aspect);
    const double near = fitNear ? unit.near : scene.near, far = fitFar ? unit.far : scene.far;
    const Mat4 projection = perspective(scene.fovy, aspect, near, far);
    for (int i = 0; i < 16; ++i) {
      if (!std::isfinite(projection.val[i])) {
        failKey(at("project"), "project",
                "fovy " + formatNumber(scene.fovy) + ", aspect " + formatNumber(aspect) +
                    ", near " + formatNumber(scene.near) + " and far " + formatNumber(scene.far) +
                    " overflow the projection");
      }
    }
  }
  checkMsaa(at("msaa"), scene.msaa);
  if (!std::isfinite(scene.angle)) {
    failKey(at("angle"), "angle", "expected a finite number, got " + formatNumber(scene.angle));
  }
  checkDirection(at("axis"), "axis", scene.axis);
  checkDirection(at("up"), "up", scene.up);
  checkFinite(at("target"), "target", scene.target);
  for (int c : scene.background) {
    if (c < 0 || c > 255) {
      failKey(at("background"), "background",
              "expected 3 integers from 0 to 255, got [" + std::to_string(scene.background[0]) +
                  ", " + std::to_string(scene.background[1]) + ", " +
                  std::to_string(scene.background[2]) + "]");
    }
  }
  if (scene.grid) {
    checkGridCount(at("grid.count"), scene.grid->count);
    checkFinite(at("grid.spacing"), "grid.spacing", scene.grid->spacing);
  }

  // Without an eye, fit still keeps the default viewing direction, down -z (makeCamera puts
  // the eye at target + (0, 0, 1)), so up must not be parallel to it either.
  cv::Vec3d direction(0.0, 0.0, -1.0);
  std::string directionName = "the default viewing direction (no eye given) ";
  if (!scene.eye) {
    if (!scene.fit) failKey(at("eye"), "eye", "missing (required unless fit is on)");
  } else if (scene.fit && keep.eye && !keep.target) {
    // The target will be the model's centre: makeCamera checks the direction then.
    checkFinite(at("eye"), "eye", *scene.eye);
    return;
  } else {
    const cv::Vec3d eye = *scene.eye;
    checkFinite(at("eye"), "eye", eye);
    direction = scene.target - eye;
    directionName = "the viewing direction target - eye ";
    if (!isUsableDirection(direction)) {
      failKey(at("eye"), "eye",
              "must differ from target " + formatVec(scene.target) + ", got " + formatVec(eye));
    }
  }
  // lookAt needs a right vector up x direction; fit keeps both (SPEC §4), so the rule holds
  // with fit too.
  // Unit vectors first: the cross product of raw large vectors could overflow.
  const cv::Vec3d right = (direction / cv::norm(direction)).cross(scene.up / cv::norm(scene.up));
  const double sine = cv::norm(right);
  if (!(sine > 1e-9)) {
    failKey(at("up"), "up",
            "must not be parallel to " + directionName + formatVec(direction) + ", got " +
                formatVec(scene.up));
  }
}

}  // namespace zrender
