#include <chrono>

#include "camera_config.h"
#include "sim_modules.h"

namespace touchline::nao {

namespace {
double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::uint8_t clampByte(double v) { return static_cast<std::uint8_t>(v < 0 ? 0 : v > 255 ? 255 : v); }

// Converts packed RGB to the raw layout NAOqi uses for a colour space; returns layers.
int convert(const std::vector<std::uint8_t>& rgb, std::uint32_t cs, std::string& out) {
  std::size_t pixels = rgb.size() / 3;
  auto yuv = [](const std::uint8_t* p, double& y, double& u, double& v) {
    y = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    u = 128 - 0.168736 * p[0] - 0.331264 * p[1] + 0.5 * p[2];
    v = 128 + 0.5 * p[0] - 0.418688 * p[1] - 0.081312 * p[2];
  };
  double y, u, v;
  switch (cs) {
    case 11:  // kRGB
      out.assign(rgb.begin(), rgb.end());
      return 3;
    case 13:  // kBGR
      out.resize(rgb.size());
      for (std::size_t i = 0; i < pixels; ++i) {
        out[3 * i] = static_cast<char>(rgb[3 * i + 2]);
        out[3 * i + 1] = static_cast<char>(rgb[3 * i + 1]);
        out[3 * i + 2] = static_cast<char>(rgb[3 * i]);
      }
      return 3;
    case 10:  // kYUV
      out.resize(rgb.size());
      for (std::size_t i = 0; i < pixels; ++i) {
        yuv(&rgb[3 * i], y, u, v);
        out[3 * i] = static_cast<char>(clampByte(y));
        out[3 * i + 1] = static_cast<char>(clampByte(u));
        out[3 * i + 2] = static_cast<char>(clampByte(v));
      }
      return 3;
    case 9:  // kYUV422: Y0 U Y1 V per pixel pair
      out.resize(pixels * 2);
      for (std::size_t i = 0; i + 1 < pixels; i += 2) {
        double y1, u1, v1;
        yuv(&rgb[3 * i], y, u, v);
        yuv(&rgb[3 * i + 3], y1, u1, v1);
        out[2 * i] = static_cast<char>(clampByte(y));
        out[2 * i + 1] = static_cast<char>(clampByte((u + u1) / 2));
        out[2 * i + 2] = static_cast<char>(clampByte(y1));
        out[2 * i + 3] = static_cast<char>(clampByte((v + v1) / 2));
      }
      return 2;
    case 0:  // kYuv: Y only
      out.resize(pixels);
      for (std::size_t i = 0; i < pixels; ++i) {
        yuv(&rgb[3 * i], y, u, v);
        out[i] = static_cast<char>(clampByte(y));
      }
      return 1;
    default:
      throw CallError("getImageRemote: colour space " + std::to_string(cs) +
                      " is not rendered by the simulator (0, 9, 10, 11, 13 are)");
  }
}
}  // namespace

SimVideo::SimVideo() : SimModule("ALVideoDevice", "Synthetic camera images (raw, uncompressed).") {
  add({"subscribe",
       {{"name", ParamType::String}, {"resolution", ParamType::Int}, {"colorSpace", ParamType::Int},
        {"fps", ParamType::Int}},
       "str", "1.x API: subscribes to the active camera; returns the subscriber id.",
       [this](const Params& p) {
         std::uint32_t camera;
         {
           std::lock_guard<std::mutex> lock(mutex_);
           camera = activeCamera_;
         }
         return std::optional<Value>(stringValue(
             subscribe(stringArg(p, 0), {camera, intArg(p, 1), intArg(p, 2), intArg(p, 3)})));
       }});
  add({"subscribeCamera",
       {{"name", ParamType::String}, {"cameraIndex", ParamType::Int}, {"resolution", ParamType::Int},
        {"colorSpace", ParamType::Int}, {"fps", ParamType::Int}},
       "str", "2.x API: subscribes to camera 0 (top) or 1 (bottom).", [this](const Params& p) {
         if (intArg(p, 1) > 1) throw CallError("cameraIndex must be 0 (top) or 1 (bottom)");
         return std::optional<Value>(stringValue(subscribe(
             stringArg(p, 0), {intArg(p, 1), intArg(p, 2), intArg(p, 3), intArg(p, 4)})));
       }});
  add({"unsubscribe", {{"nameId", ParamType::String}}, "bool", "Removes a subscriber.",
       [this](const Params& p) {
         std::lock_guard<std::mutex> lock(mutex_);
         return std::optional<Value>(boolValue(subscribers_.erase(stringArg(p, 0)) > 0));
       }});
  add({"getSubscribers", {}, "Vec<str>", "Subscriber ids.", [this](const Params&) {
         std::lock_guard<std::mutex> lock(mutex_);
         std::vector<std::string> names;
         for (const auto& [name, s] : subscribers_) names.push_back(name);
         return std::optional<Value>(stringList(names));
       }});
  add({"setActiveCamera", {{"cameraIndex", ParamType::Int}}, "bool", "0 top, 1 bottom.",
       [this](const Params& p) {
         if (intArg(p, 0) > 1) throw CallError("cameraIndex must be 0 (top) or 1 (bottom)");
         std::lock_guard<std::mutex> lock(mutex_);
         activeCamera_ = intArg(p, 0);
         return std::optional<Value>(boolValue(true));
       }});
  add({"getActiveCamera", {}, "int", "0 top, 1 bottom.", [this](const Params&) {
         std::lock_guard<std::mutex> lock(mutex_);
         return std::optional<Value>(intValue(activeCamera_));
       }});
  add({"getImageRemote", {{"nameId", ParamType::String}}, "any",
       "ALImage: [width, height, layers, colorSpace, timeSec, timeUsec, binary, cameraIndex].",
       [this](const Params& p) {
         std::lock_guard<std::mutex> lock(mutex_);
         auto it = subscribers_.find(stringArg(p, 0));
         if (it == subscribers_.end()) throw CallError("no subscriber '" + stringArg(p, 0) + "'");
         return std::optional<Value>(image(it->second));
       }});
  add({"releaseImage", {{"nameId", ParamType::String}}, "void", "No-op (images are copies).",
       [](const Params&) { return none(); }});
  // getImageRemote renders a frame (milliseconds at kVGA and above): it goes to a worker.
  markQuick({"subscribe", "subscribeCamera", "unsubscribe", "getSubscribers", "setActiveCamera",
             "getActiveCamera", "releaseImage"});
}

std::string SimVideo::subscribe(const std::string& name, Subscriber s) {
  if (auto error = validateCamera({s.resolution, s.colorSpace, s.fps})) throw CallError(*error);
  std::lock_guard<std::mutex> lock(mutex_);
  // NAOqi appends _<n> when a name is taken ("the same Name could be used only six time").
  std::string id = name;
  for (int n = 0; subscribers_.count(id); ++n) {
    if (n >= 6) throw CallError("subscriber name '" + name + "' used too often");
    id = name + "_" + std::to_string(n);
  }
  subscribers_[id] = s;
  return id;
}

Value SimVideo::image(const Subscriber& s) {
  auto [w, h] = *resolutionSize(s.resolution);
  double t = nowSeconds();
  std::string raw;
  int layers = convert(renderer_.render(w, h, t), s.colorSpace, raw);
  auto sec = static_cast<std::uint32_t>(t);
  auto usec = static_cast<std::uint32_t>((t - sec) * 1e6);
  return arrayValue({intValue(w), intValue(h), intValue(layers), intValue(s.colorSpace),
                     intValue(sec), intValue(usec), binaryValue(std::move(raw)), intValue(s.camera)});
}

}  // namespace touchline::nao
