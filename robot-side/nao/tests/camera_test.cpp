#include <gtest/gtest.h>
#include <turbojpeg.h>

#include <chrono>

#include "camera_server.h"
#include "rpc_client.h"

using namespace touchline::nao;
using namespace std::chrono_literals;

namespace {

class CameraTest : public ::testing::Test {
 protected:
  CameraTest() : server_(CameraOptions{"127.0.0.1", 0}), client_(context_, loopback(server_.port())) {}

  ::nao::CamResponse request(const std::string& payload) {
    auto reply = client_.roundTrip(payload, 30000ms);
    EXPECT_TRUE(reply) << "camera request timed out";
    ::nao::CamResponse response;
    EXPECT_TRUE(response.ParseFromString(reply.value_or("")));
    lastReplySize_ = reply ? reply->size() : 0;
    return response;
  }

  ::nao::CamResponse configure(std::optional<std::uint32_t> resolution,
                               std::optional<std::uint32_t> colorSpace,
                               std::optional<std::uint32_t> fps) {
    ::nao::CamRequest r;
    if (resolution) r.set_resolution(*resolution);
    if (colorSpace) r.set_colorspace(*colorSpace);
    if (fps) r.set_fps(*fps);
    return request(r.SerializeAsString());
  }

  CameraServer server_;
  zmq::context_t context_;
  DealerClient client_;
  std::size_t lastReplySize_ = 0;
};

struct JpegInfo {
  int width = 0, height = 0, subsampling = -1;
};

JpegInfo jpegInfo(const std::string& jpeg) {
  JpegInfo info;
  tjhandle h = tjInitDecompress();
  int colorspace = 0;
  if (tjDecompressHeader3(h, reinterpret_cast<const unsigned char*>(jpeg.data()), jpeg.size(),
                          &info.width, &info.height, &info.subsampling, &colorspace) != 0) {
    info = {};
  }
  tjDestroy(h);
  return info;
}

}  // namespace

TEST_F(CameraTest, FetchBeforeConfigurationIsAnError) {
  auto response = request("");
  EXPECT_FALSE(response.has_imagedata());
  EXPECT_NE(response.error().find("not configured"), std::string::npos);
}

TEST_F(CameraTest, ConfigureThenFetchAJpeg) {
  auto configured = configure(2, 11, 30);
  EXPECT_FALSE(configured.has_error());
  EXPECT_FALSE(configured.has_imagedata());
  EXPECT_EQ(lastReplySize_, 0u);  // an empty CamResponse
  auto frame = request("");
  ASSERT_TRUE(frame.has_imagedata()) << frame.error();
  auto info = jpegInfo(frame.imagedata());
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.height, 480);
  EXPECT_EQ(info.subsampling, TJSAMP_420);
  EXPECT_LE(frame.imagedata().size(), 640u * 480u * 3u / 15u);
}

TEST_F(CameraTest, UnsetFieldsKeepTheirValue) {
  configure(3, 11, 10);
  configure(std::nullopt, std::nullopt, 5);  // only fps
  auto info = jpegInfo(request("").imagedata());
  EXPECT_EQ(info.width, 1280);
  EXPECT_EQ(info.height, 960);
  configure(0, 0, std::nullopt);  // single-channel colour space: grey JPEG
  info = jpegInfo(request("").imagedata());
  EXPECT_EQ(info.width, 160);
  EXPECT_EQ(info.subsampling, TJSAMP_GRAY);
}

TEST_F(CameraTest, BadConfigurationsAreErrorsAndKeepTheOldOne) {
  configure(1, 11, 15);
  EXPECT_NE(configure(7, std::nullopt, std::nullopt).error().find("unknown resolution 7"), std::string::npos);
  EXPECT_NE(configure(std::nullopt, 99, std::nullopt).error().find("unknown colour space 99"), std::string::npos);
  EXPECT_NE(configure(std::nullopt, std::nullopt, 0).error().find("outside 1..30"), std::string::npos);
  EXPECT_NE(configure(std::nullopt, std::nullopt, 31).error().find("outside 1..30"), std::string::npos);
  EXPECT_EQ(jpegInfo(request("").imagedata()).width, 320);
}

TEST_F(CameraTest, GarbageIsAnErrorAndServingContinues) {
  EXPECT_NE(request("\xff\xff\xff\xff").error().find("not a CamRequest"), std::string::npos);
  client_.sendFrames({"x", "y", "z", "w"});  // wrong layout: dropped
  configure(0, 11, 30);
  EXPECT_TRUE(request("").has_imagedata());
  EXPECT_EQ(server_.counters().malformedEnvelopes, 1u);
}

TEST_F(CameraTest, FramesMoveAndAreRenderedAtMostOncePerPeriod) {
  configure(0, 11, 30);
  std::string first = request("").imagedata();
  auto start = std::chrono::steady_clock::now();
  std::string later;
  do {
    later = request("").imagedata();
  } while (later == first && std::chrono::steady_clock::now() - start < 2s);
  EXPECT_NE(first, later) << "the scene should move between frames";
  EXPECT_LE(server_.counters().framesRendered, 3u + 30u * 2u);
}
