// The flow-field figure from real snapshots (original and flux-shuffled gas, ε = 0.93, n = 0.05,
// N = 5000): every file written and non-empty; bad panels rejected with the field named.
#define BOOST_TEST_MODULE figures_flow_field
#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "molchaos/figures/render.hpp"
#include "molchaos/validation/flow_field.hpp"

namespace fs = std::filesystem;
using namespace molchaos;

BOOST_AUTO_TEST_CASE(renders_original_and_shuffled_gas) {
  const char* keep = std::getenv("MOLCHAOS_FLOW_FIELD_DIR");  // to look at the figure
  const fs::path dir = keep ? fs::path(keep) : fs::temp_directory_path() / "molchaos_flow_field";
  fs::remove_all(dir);
  const auto data = validation::flow_field_data();
  BOOST_TEST_REQUIRE(data.rows.size() == 3u);
  for (const auto& row : data.rows) BOOST_TEST_REQUIRE(row.size() == 2u);
  figures::RenderOptions o;
  o.output_directory = dir.string();
  const auto out = figures::render_flow_field(data, o);
  BOOST_TEST(out.files.size() == 3u);
  for (const auto& f : out.files) BOOST_TEST(fs::file_size(f) > 1000u, f);
  if (!keep) fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(rejects_mismatched_panels) {
  validation::FlowFieldData data;
  validation::FlowFieldPanel p;
  p.box = 10;
  p.cells = 4;
  p.density_noise = p.vorticity_noise = 1.0;
  p.vx.assign(16, 0.0);
  p.vy.assign(15, 0.0);
  p.vorticity.assign(16, 0.0);
  p.relative_density.assign(16, 1.0);
  data.rows = {{p}};
  figures::RenderOptions o;
  o.output_directory = (fs::temp_directory_path() / "molchaos_flow_field_bad").string();
  BOOST_CHECK_THROW(figures::render_flow_field(data, o), std::invalid_argument);
}

namespace {

// Frames (image descriptors) of a GIF file, by walking its blocks (GIF89a specification):
// header and screen descriptor, global colour table, then extensions and images up to 0x3B.
int gif_frame_count(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string b{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (b.rfind("GIF89a", 0) != 0) throw std::runtime_error("not a GIF89a file");
  auto byte = [&](std::size_t k) {
    return static_cast<unsigned>(static_cast<unsigned char>(b.at(k)));
  };
  auto colour_table = [](unsigned flags) { return flags & 0x80 ? 3u << ((flags & 7) + 1) : 0u; };
  std::size_t i = 13 + colour_table(byte(10));
  auto skip_sub_blocks = [&] {
    while (byte(i) != 0) i += byte(i) + 1;
    ++i;
  };
  int frames = 0;
  for (;;) {
    const unsigned block = byte(i++);
    if (block == 0x3B) return frames;
    if (block == 0x21) {  // extension: label, then sub-blocks
      ++i;
      skip_sub_blocks();
      continue;
    }
    if (block != 0x2C) throw std::runtime_error("unexpected GIF block");
    ++frames;
    i += 9 + colour_table(byte(i + 8));  // image descriptor, local colour table
    ++i;                                 // LZW minimum code size
    skip_sub_blocks();
  }
}

validation::FlowFieldPanel uniform_panel(double vorticity) {
  validation::FlowFieldPanel p;
  p.title = "test";
  p.box = 10;
  p.cells = 4;
  p.density_noise = p.vorticity_noise = 1.0;
  p.vx.assign(16, 0.1);
  p.vy.assign(16, -0.1);
  p.vorticity.assign(16, vorticity);
  p.relative_density.assign(16, 1.0);
  return p;
}

}  // namespace

// One frame per row of the data, whatever the rows hold; the probe tells a missing terminal.
BOOST_AUTO_TEST_CASE(animation_has_one_frame_per_time) {
  figures::RenderOptions o;
  o.output_directory = (fs::temp_directory_path() / "molchaos_flow_animation").string();
  BOOST_TEST(!figures::gnuplot_has_terminal("no_such_terminal", o));
  if (!figures::gnuplot_has_terminal("gif", o)) {
    BOOST_TEST_MESSAGE("gnuplot here has no gif terminal: animation not tested");
    return;
  }
  fs::remove_all(o.output_directory);
  validation::FlowFieldData data;
  for (int frame = 0; frame < 5; ++frame)
    data.rows.push_back({uniform_panel(frame), uniform_panel(-frame)});
  const auto out = figures::render_flow_field_animation(data, o);
  BOOST_TEST_REQUIRE(out.files.size() == 2u);  // the GIF and its script
  const fs::path gif = fs::path(o.output_directory) / "fig_flow_field.gif";
  BOOST_TEST(fs::exists(fs::path(o.output_directory) / "fig_flow_field_animation.gp"));
  BOOST_TEST(gif_frame_count(gif) == 5);
  fs::remove_all(o.output_directory);
}
