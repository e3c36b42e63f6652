#include "zrender/cli/CameraManifest.hpp"

#include <cmath>
#include <memory>
#include <sstream>

namespace zrender {

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

Json::Value matrixJson(const Mat4& m) {
  Json::Value rows(Json::arrayValue);
  for (int r = 0; r < 4; ++r) {
    Json::Value row(Json::arrayValue);
    for (int c = 0; c < 4; ++c) row.append(m(r, c));
    rows.append(row);
  }
  return rows;
}

// The pinhole intrinsics of a camera, pixels and radians: the focal lengths that map the
// tangent of a ray's angle to pixels, and the principal point at the image's centre (pixel
// (i, j) covers [i, i + 1) x [j, j + 1), as the viewport rule has it).
struct Intrinsics {
  double flX, flY, cx, cy, angleX, angleY;
};

Intrinsics intrinsics(const Camera& camera) {
  const double tanY = std::tan(camera.fovy * kPi / 360.0);
  const double tanX = tanY * camera.aspect;
  Intrinsics in{};
  in.flX = camera.width / (2.0 * tanX);
  in.flY = camera.height / (2.0 * tanY);
  in.cx = camera.width / 2.0;
  in.cy = camera.height / 2.0;
  in.angleX = 2.0 * std::atan(tanX);
  in.angleY = 2.0 * std::atan(tanY);
  return in;
}

void putIntrinsics(Json::Value& j, const Intrinsics& in) {
  j["fl_x"] = in.flX;
  j["fl_y"] = in.flY;
  j["camera_angle_x"] = in.angleX;
  j["camera_angle_y"] = in.angleY;
}

// `file` relative to `folder`, both made absolute and normalized (no link is followed: the
// same text from every working folder that names the same files).
std::string relativeTo(const fs::path& file, const fs::path& folder) {
  const fs::path a = fs::absolute(file).lexically_normal();
  const fs::path b = fs::absolute(folder).lexically_normal();
  const fs::path r = a.lexically_relative(b);
  return (r.empty() ? a : r).generic_string();
}

}  // namespace

Json::Value cameraManifest(const std::vector<Camera>& cameras, const RenderOutputs& outputs,
                           const fs::path& manifest, int msaa) {
  const fs::path folder = manifest.parent_path().empty() ? fs::path(".") : manifest.parent_path();
  Json::Value root(Json::objectValue);
  const Intrinsics first = intrinsics(cameras.front());
  root["w"] = cameras.front().width;
  root["h"] = cameras.front().height;
  putIntrinsics(root, first);
  root["cx"] = first.cx;
  root["cy"] = first.cy;
  root["k1"] = 0.0;
  root["k2"] = 0.0;
  root["p1"] = 0.0;
  root["p2"] = 0.0;
  root["camera_model"] = "OPENCV";
  Json::Value own(Json::objectValue);
  own["version"] = ZRENDER_VERSION;
  own["scene"] = outputs.fields.scene;
  own["algorithm"] = outputs.fields.algorithm;
  own["shading"] = outputs.fields.shading;
  own["msaa"] = msaa;
  own["conventions"] =
      "transform_matrix: camera to world, OpenGL camera axes (looking down -Z, +Y up, +X "
      "right). view_matrix is its inverse, world to camera. projection_matrix: camera to clip "
      "space, OpenGL; window depth = (z_ndc + 1) / 2 in the depth images. Rows of 4.";
  root["zrender"] = own;

  Json::Value frames(Json::arrayValue);
  for (size_t v = 0; v < cameras.size(); ++v) {
    const Camera& camera = cameras[v];
    const ViewFiles files = outputs.filesOf(v);
    Json::Value frame(Json::objectValue);
    frame["file_path"] = relativeTo(files.color, folder);
    frame["transform_matrix"] = matrixJson(camera.view.inv(cv::DECOMP_LU));
    const Intrinsics in = intrinsics(camera);
    if (in.flX != first.flX || in.flY != first.flY) putIntrinsics(frame, in);
    Json::Value mine(Json::objectValue);
    mine["view"] = Json::UInt64(v);
    mine["near"] = camera.near;
    mine["far"] = camera.far;
    mine["view_matrix"] = matrixJson(camera.view);
    mine["projection_matrix"] = matrixJson(camera.projection);
    if (files.depth) mine["depth_file_path"] = relativeTo(*files.depth, folder);
    if (files.ids) mine["ids_file_path"] = relativeTo(*files.ids, folder);
    if (files.normals) mine["normals_file_path"] = relativeTo(*files.normals, folder);
    frame["zrender"] = mine;
    frames.append(frame);
  }
  root["frames"] = frames;
  return root;
}

std::string manifestText(const Json::Value& manifest) {
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "  ";
  builder["precision"] = 17;
  return Json::writeString(builder, manifest) + "\n";
}

}  // namespace zrender
