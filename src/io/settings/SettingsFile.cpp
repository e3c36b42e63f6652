#include "zrender/io/settings/SettingsFile.hpp"

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

#include "zrender/scene/SceneValidation.hpp"
#include "zrender/scene/SettingsMessages.hpp"

namespace zrender {

namespace {

namespace fs = std::filesystem;

// A settings file is a few kilobytes; the cap keeps `--settings /dev/zero` from hanging.
constexpr std::size_t kMaxSettingsBytes = 64u << 20;
// settings.json nests at most three levels (scene, grid, array); the cap turns a pathological
// "[[[[..." into a clean error instead of deep recursion.
constexpr int kJsonStackLimit = 64;
// Longest excerpt of the offending value quoted after "got".
constexpr std::size_t kMaxSettingsExcerpt = 60;

// Keys of a scene and of its grid (docs/design.md, Settings); any other key is warned about and
// ignored.
const std::set<std::string> kSceneKeys{"path",    "width", "height",  "eye",     "target",
                                       "up",      "angle", "axis",    "project", "fit",
                                       "shading", "msaa",  "cull",    "texture", "background",
                                       "grid",    "bench", "objects", "views"};
const std::set<std::string> kObjectKeys{"path", "translate", "rotate", "scale", "texture", "color"};
const std::set<std::string> kGridKeys{"count", "spacing"};
const std::set<std::string> kViewKeys{"eye", "target", "up", "azimuth", "elevation", "zoom"};

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
  if (flat.size() > kMaxSettingsExcerpt) {
    std::size_t cut = kMaxSettingsExcerpt;
    // Do not split a UTF-8 sequence: back up over continuation bytes.
    while (cut > 0 && (static_cast<unsigned char>(flat[cut]) & 0xC0) == 0x80) --cut;
    while (cut > 0 && flat[cut - 1] == ' ') --cut;
    flat.resize(cut);
    flat += "...";
  }
  return printable(flat);
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

  // The "objects" list: each its path, placement and color (docs/design.md, Settings).
  std::vector<SceneObject> readObjects(const Json::Value& v, Warnings& warnings) const {
    if (!v.isArray() || v.empty())
      fail("objects", "expected a non-empty array of objects" + got(v));
    std::vector<SceneObject> objects;
    for (Json::ArrayIndex i = 0; i < v.size(); ++i) {
      const Json::Value& o = v[i];
      const std::string key = "objects[" + std::to_string(i) + "]";
      if (!o.isObject()) fail(key, "expected an object with a \"path\"" + got(o));
      for (const auto& name : o.getMemberNames()) {
        if (!kObjectKeys.count(name)) {
          warnings.push_back(where_ + ": unknown key '" + key + "." + printable(name) +
                             "' (ignored)");
        }
      }
      SceneObject object;
      if (!o.isMember("path")) fail(key + ".path", "missing");
      object.path = readPath(o["path"], key + ".path");
      if (o.isMember("translate")) object.translate = readVec3(o["translate"], key + ".translate");
      if (o.isMember("rotate")) {
        // [angle, [x, y, z]]: degrees about the axis, as the scene's angle and axis.
        const Json::Value& r = o["rotate"];
        bool ok = r.isArray() && r.size() == 2 && finiteNumber(r[0], object.angle) &&
                  r[1].isArray() && r[1].size() == 3;
        for (Json::ArrayIndex a = 0; ok && a < 3; ++a) ok = finiteNumber(r[1][a], object.axis[a]);
        if (!ok) fail(key + ".rotate", "expected [angle, [x, y, z]]" + got(r));
        checkDirection(where_, key + ".rotate", object.axis);
      }
      if (o.isMember("scale")) {
        const Json::Value& sc = o["scale"];
        double f = 0.0;
        if (finiteNumber(sc, f))
          object.scale = cv::Vec3d(f, f, f);
        else
          object.scale = readVec3(sc, key + ".scale");
        for (int a = 0; a < 3; ++a) {
          if (!(object.scale[a] != 0.0))
            fail(key + ".scale", "expected non-zero factors" + got(sc));
        }
      }
      if (o.isMember("texture")) object.texture = readPath(o["texture"], key + ".texture");
      if (o.isMember("color")) {
        const cv::Vec3d c = readVec3(o["color"], key + ".color");
        for (int a = 0; a < 3; ++a) {
          if (c[a] < 0.0 || c[a] > 1.0)
            fail(key + ".color", "expected 3 numbers from 0 to 1" + got(o["color"]));
        }
        object.color = c;
      }
      objects.push_back(std::move(object));
    }
    return objects;
  }

  // The "views" list: each a camera in full, or relative to the scene's (docs/design.md, Views).
  std::vector<ViewSpec> readViews(const Json::Value& v, Warnings& warnings) const {
    if (!v.isArray() || v.empty()) fail("views", "expected a non-empty array of views" + got(v));
    std::vector<ViewSpec> views;
    for (Json::ArrayIndex i = 0; i < v.size(); ++i) {
      const Json::Value& o = v[i];
      const std::string key = "views[" + std::to_string(i) + "]";
      if (!o.isObject()) {
        fail(key, "expected an object of eye, target, up, azimuth, elevation, zoom" + got(o));
      }
      for (const auto& name : o.getMemberNames()) {
        if (!kViewKeys.count(name)) {
          warnings.push_back(where_ + ": unknown key '" + key + "." + printable(name) +
                             "' (ignored)");
        }
      }
      ViewSpec view;
      if (o.isMember("eye")) view.eye = readVec3(o["eye"], key + ".eye");
      if (o.isMember("target")) view.target = readVec3(o["target"], key + ".target");
      if (o.isMember("up")) {
        view.up = readVec3(o["up"], key + ".up");
        checkDirection(where_, key + ".up", *view.up);
      }
      if (o.isMember("azimuth")) view.azimuth = readNumber(o["azimuth"], key + ".azimuth");
      if (o.isMember("elevation")) view.elevation = readNumber(o["elevation"], key + ".elevation");
      if (o.isMember("zoom")) {
        view.zoom = readNumber(o["zoom"], key + ".zoom");
        if (!(view.zoom > 0.0)) fail(key + ".zoom", "expected a number above 0" + got(o["zoom"]));
      }
      views.push_back(view);
    }
    return views;
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
  if (object.isMember("objects")) {
    if (object.isMember("path")) fail("path", "give either \"path\" or \"objects\", not both");
    scene.objects = readObjects(object["objects"], warnings);
    scene.modelPath = scene.objects.front().path;
  } else {
    if (!object.isMember("path")) fail("path", "missing");
    scene.modelPath = readPath(object["path"], "path");
  }
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
  if (object.isMember("views")) scene.views = readViews(object["views"], warnings);
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

}  // namespace zrender
