// The flow-field figure from real snapshots (original and flux-shuffled gas, ε = 0.93, n = 0.05,
// N = 5000): every file written and non-empty; bad panels rejected with the field named.
#define BOOST_TEST_MODULE figures_flow_field
#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <filesystem>

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
  p.vx.assign(16, 0.0);
  p.vy.assign(15, 0.0);
  p.vorticity.assign(16, 0.0);
  p.relative_density.assign(16, 1.0);
  data.rows = {{p}};
  figures::RenderOptions o;
  o.output_directory = (fs::temp_directory_path() / "molchaos_flow_field_bad").string();
  BOOST_CHECK_THROW(figures::render_flow_field(data, o), std::invalid_argument);
}
