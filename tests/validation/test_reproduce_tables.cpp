// The tables `molchaos reproduce` writes for other tools, from small synthetic results: every
// point of Fig. 4 (the MD gases and DSMC) in fig4_A_of_eps.csv; every gas's a2 and the Sonine
// theory's in a2_of_eps.csv; the a2(ε) figure in REPORT.md with its caption.
#define BOOST_TEST_MODULE validation_reproduce_tables
#include <boost/test/unit_test.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "molchaos/validation/report.hpp"

using namespace molchaos;
using namespace molchaos::validation;

namespace {

PointResult point(double density, double restitution, const std::string& mode, double A,
                  double a2) {
  PointResult p;
  p.summary.dimension = 2;
  p.summary.density = density;
  p.summary.restitution = restitution;
  p.summary.mode = mode;
  p.summary.runs = 4;
  p.summary.A = {A, 0.01};
  p.summary.a2 = {a2, 0.002};
  return p;
}

// Two MD modes and DSMC (which sweeps summarise as mode none) at two restitutions, n = 0.05.
ReproduceResults synthetic_results() {
  ReproduceResults r;
  r.version = "test";
  r.config.densities = {0.05};
  r.config.restitutions = {0.8, 0.9};
  r.dsmc_spec.seeds = 16;
  for (double e : r.config.restitutions) {
    r.fig4_points.push_back(point(0.05, e, "none", 10.5, 0.01));
    r.fig4_points.push_back(point(0.05, e, "flux", 10.0, 0.02));
    r.dsmc_points.push_back(point(0.05, e, "none", 9.9, 0.03));
  }
  return r;
}

// The data rows (no '#' header) of a CSV text, the column line first.
std::vector<std::string> data_lines(const std::string& csv) {
  std::vector<std::string> lines;
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);)
    if (!line.starts_with("#")) lines.push_back(line);
  return lines;
}

}  // namespace

BOOST_AUTO_TEST_CASE(fig4_csv_holds_every_point_dsmc_included) {
  const ReproduceResults r = synthetic_results();
  const std::string csv = fig4_csv(r);
  const auto lines = data_lines(csv);
  BOOST_TEST_REQUIRE(lines.size() == 1u + 6u);
  BOOST_TEST(lines[0].starts_with("density,restitution,randomize,A,A_err,runs"));
  int dsmc = 0;
  for (std::size_t k = 1; k < lines.size(); ++k)
    if (lines[k].find(",dsmc,") != std::string::npos) {
      ++dsmc;
      BOOST_TEST(lines[k].find(",dsmc,9.9,0.01,4,") != std::string::npos);
    }
  BOOST_TEST(dsmc == 2);
  BOOST_TEST(csv.find("# dsmc_seeds = 16") != std::string::npos);
}

// reproduce --seeds 1: a point of one run has its values but no standard errors (nan, not 0).
BOOST_AUTO_TEST_CASE(fig4_csv_gives_no_error_bar_for_one_run) {
  ReproduceResults r = synthetic_results();
  for (auto& p : r.fig4_points) {
    p.summary.runs = 1;
    p.summary.A.error = p.summary.a2.error = p.summary.mean_dyad.error = 0.0;
  }
  const auto lines = data_lines(fig4_csv(r));
  BOOST_TEST_REQUIRE(lines.size() == 1u + 6u);
  BOOST_TEST(lines[1] == "0.05,0.8,none,10.5,nan,1,0,0,0.01,nan,0,nan,0");
}

BOOST_AUTO_TEST_CASE(a2_csv_holds_every_gas_and_both_theory_levels) {
  ReproduceResults r = synthetic_results();
  A2Panel panel;
  panel.density = 0.05;
  // The original gas's first point has one run (reproduce --seeds 1): no error (nan, not 0).
  panel.series.push_back({"original", "none", {0.8, 0.9}, {{0.01, 0.0}, {0.02, 0.002}}, {1, 8}});
  panel.series.push_back({"DSMC", "dsmc", {0.8, 0.9}, {{0.03, 0.001}, {0.04, 0.001}}, {8, 8}});
  panel.theory_restitution = {0.8, 0.805, 0.81};
  panel.first_sonine = {{-0.02, 0.0}, {-0.021, 0.0}, {-0.022, 0.0}};
  panel.improved = {{-0.025, 1e-13}, {-0.026, 1e-13}, {-0.027, 1e-13}};
  r.a2.panels = {panel};
  const std::string csv = a2_csv(r);
  const auto lines = data_lines(csv);
  BOOST_TEST_REQUIRE(lines.size() == 1u + 4u + 6u);
  BOOST_TEST(lines[0] == "dimension,density,restitution,source,a2,a2_err");
  BOOST_TEST(lines[1] == "2,0.05,0.8,none,0.01,nan");
  BOOST_TEST(lines[2] == "2,0.05,0.9,none,0.02,0.002");
  BOOST_TEST(lines[3] == "2,0.05,0.8,dsmc,0.03,0.001");
  BOOST_TEST(lines[5] == "2,0.05,0.800,first_sonine,-0.02,0");
  BOOST_TEST(lines[10] == "2,0.05,0.810,a2_a3,-0.027,1e-13");
  BOOST_TEST(csv.starts_with("# molchaos reproduce"));
}

// The report embeds every figure the reproduction renders with a caption saying what to look at.
BOOST_AUTO_TEST_CASE(every_figure_has_a_caption) {
  const ReproduceResults r = synthetic_results();
  for (const char* file :
       {"fig3_temperature.png", "fig4_A_of_eps.png", "fig_b_of_eps.png", "fig_a2_of_eps.png",
        "fig_snapshot.png", "fig_pair_correlations.png", "fig_contact_moments.png",
        "fig_cooling_decomposition.png", "fig_impact_parameter.png", "fig_flow_field.png",
        "fig_structure_factor.png", "fig_structure_factor_3d.png"}) {
    BOOST_TEST_INFO(file);
    const std::string caption = figure_caption(file, r);
    BOOST_TEST((caption.find("Look ") != std::string::npos ||
                caption.find("look ") != std::string::npos));
  }
  const std::string report = report_markdown(r, {"fig_a2_of_eps.png"}, "test");
  BOOST_TEST(report.find("![fig_a2_of_eps.png](fig_a2_of_eps.png)") != std::string::npos);
}
