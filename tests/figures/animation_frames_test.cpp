// A sun study's figures (figures/animation_frames.h, study_statistics.h): base64 by the
// RFC's own examples, the viewer embedding every frame in order, the label band, and
// the statistics gathered one block of rows per frame.
#include "skylit/figures/animation_frames.h"

#include <gtest/gtest.h>

#include "skylit/figures/study_statistics.h"

namespace skylit {
namespace {

std::vector<uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

TEST(AnimationFrames, Base64AsRfc4648Section10) {
  const std::pair<const char*, const char*> examples[] = {{"", ""},
                                                          {"f", "Zg=="},
                                                          {"fo", "Zm8="},
                                                          {"foo", "Zm9v"},
                                                          {"foob", "Zm9vYg=="},
                                                          {"fooba", "Zm9vYmE="},
                                                          {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : examples) EXPECT_EQ(base64(bytes_of(plain)), encoded) << plain;
  EXPECT_EQ(base64({0xfb, 0xff}), "+/8=");
}

TEST(AnimationFrames, ViewerEmbedsEveryFrameInOrderWithASlider) {
  const std::vector<std::vector<uint8_t>> pngs = {bytes_of("first"), bytes_of("second"), bytes_of("third")};
  const std::string html = frame_viewer_html("a <study>", {"1/3 noon", "2/3 </script>", "3/3 \"dusk\""}, pngs, 4);
  EXPECT_NE(html.find("<title>a &lt;study&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find("type=\"range\" min=\"0\" max=\"2\""), std::string::npos);
  std::size_t at = 0;
  for (const auto& png : pngs) {
    const std::size_t found = html.find("data:image/png;base64," + base64(png), at);
    ASSERT_NE(found, std::string::npos);
    at = found + 1;  // each after the one before
  }
  // A label cannot end the script early, and nothing is fetched from elsewhere.
  EXPECT_EQ(html.find("</script>"), html.rfind("</script>"));
  EXPECT_EQ(html.find("http"), std::string::npos);
  EXPECT_NE(html.find("interval_ms = 250.0"), std::string::npos);
}

TEST(AnimationFrames, LabelNamesTheFrameAndTheBandDarkensOnlyTheBottom) {
  AnimationFrame frame;
  frame.number = 3;
  frame.time = parse_offset_date_time("2026-06-21T07:00+02:00", "t");
  frame.sun_altitude_deg = 23.44;
  EXPECT_EQ(frame_label(frame, 24), "3/24  2026-06-21 07:00+02:00  sun 23.4°");
  XyzImage grey(64, 48);
  for (float& v : grey.xyz) v = 100.0f;
  DisplayOptions display;
  display.exposure_ev = 8;
  const Raster plain(64, 48);
  const Raster labelled = labelled_frame(grey, display, "x");
  const std::vector<uint8_t> expected = display_srgb8(grey, display);
  const std::size_t above_band = 3 * 64 * static_cast<std::size_t>(48 - text_height(1) - 2);
  EXPECT_TRUE(std::equal(expected.begin(), expected.begin() + above_band, labelled.rgb.begin()));
  EXPECT_FALSE(std::equal(expected.begin(), expected.begin() + above_band + 3 * 64, labelled.rgb.begin()));
  EXPECT_LT(labelled.at(60, 47).r, expected[3 * (47 * 64 + 60)]);  // the band, right of the text
}

TEST(StudyStatistics, OneBlockOfRowsPerFrameLedByItsTime) {
  std::vector<AnimationFrame> frames(2);
  frames[0].time = parse_offset_date_time("2026-06-21T10:00Z", "t");
  frames[1] = frames[0];
  frames[1].number = 2;
  frames[1].time.hour = 11;
  RenderStatistics stats;
  stats.objects = {{"wall", {10, 5.0, 1, 9, 2, 5, 8}}};
  stats.sky = {20, 3000.0, 1000, 5000, 1100, 3000, 4900};
  RenderStatistics brighter = stats;
  brighter.objects[0].luminance.mean = 7.0;
  const std::string csv = study_statistics_csv(frames, {stats, brighter});
  EXPECT_EQ(csv.rfind("frame,date,time,utc_offset,sun_altitude_deg,kind,name,", 0), 0u);
  EXPECT_NE(csv.find("\n1,2026-06-21,10:00,Z,0.000,object,wall,10,5,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n2,2026-06-21,11:00,Z,0.000,object,wall,10,7,"), std::string::npos) << csv;
  const Plot plot = study_statistics_plot("t", frames, {stats, brighter});
  ASSERT_EQ(plot.series.size(), 2u);  // the wall and the sky
  EXPECT_EQ(plot.series[0].x, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(plot.series[0].y, (std::vector<double>{5.0, 7.0}));
}

}  // namespace
}  // namespace skylit
