// The result CSV: writer (atomic file replacement) and reader (header back into Parameters).
#include "molchaos/sim/csv.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::sim {
namespace {

const char* const k_base_columns = "t,T,a2,collisions,events,velocity_mode,density_mode";
const char* const k_contact_sum_columns =
    ",contacts,sum_c1e_c2e,sum_c1_dot_c2,sum_gn2,sum_abs_gn,sum_g2";
constexpr std::size_t k_first_impact_column = 13;  // after the base and the sum columns

// The contact columns: the sums, then the impact-parameter histogram impact_0 … impact_<bins−1>.
std::string contact_columns() {
  std::string s = k_contact_sum_columns;
  for (int b = 0; b < ContactMoments::k_impact_bins; ++b) s += ",impact_" + std::to_string(b);
  return s;
}

[[noreturn]] void corrupt(const std::string& what) {
  throw std::runtime_error("corrupt result file: " + what);
}

double parse_double(const std::string& text, const std::string& what) {
  double x = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, x);
  if (ec != std::errc() || ptr != last || text.empty()) corrupt(what + " '" + text + "'");
  return x;
}

std::uint64_t parse_uint(const std::string& text, const std::string& what) {
  std::uint64_t x = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, x);
  if (ec != std::errc() || ptr != last || text.empty()) corrupt(what + " '" + text + "'");
  return x;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, sep)) fields.push_back(field);
  if (!line.empty() && line.back() == sep) fields.emplace_back();
  return fields;
}

}  // namespace

void write_parameter_lines(const Parameters& p, std::ostream& out) {
  for (const ParameterInfo& info : parameter_table())
    if (!omitted(p, info)) out << "# " << info.name << " = " << format_value(p, info) << "\n";
}

void write_csv(const RunResult& r, std::ostream& out) {
  const Parameters& p = r.parameters;
  const char* particles = p.dimension == 2 ? "disks" : "spheres";
  out << k_run_title
      << (p.method == Method::dsmc
              ? ": DSMC of the homogeneous Enskog-Boltzmann equation of inelastic hard "
              : ": event-driven MD of inelastic hard ")
      << particles << " (sigma = m = 1, T0 = 1)\n"
      << "# version = " << r.version << "\n";
  write_parameter_lines(p, out);
  out << "# stop_reason = " << stop_message(r) << "\n"
      << "# collisions = " << r.collisions << "\n"
      << "# events = " << r.events << "\n"
      << "# rows = " << r.samples.size() << "\n"
      << k_base_columns << (p.contact_statistics ? contact_columns() : "") << "\n";
  for (const Sample& s : r.samples) {
    out << round_trip_text(s.t) << ',' << round_trip_text(s.temperature) << ','
        << round_trip_text(s.a2) << ',' << s.collisions << ',' << s.events << ','
        << round_trip_text(s.velocity_mode) << ',' << round_trip_text(s.density_mode);
    if (p.contact_statistics) {
      const ContactMoments& c = s.contacts;
      out << ',' << c.count << ',' << round_trip_text(c.sum_c1e_c2e) << ','
          << round_trip_text(c.sum_c1_dot_c2) << ',' << round_trip_text(c.sum_gn2) << ','
          << round_trip_text(c.sum_abs_gn) << ',' << round_trip_text(c.sum_g2);
      for (const auto count : c.impact_histogram) out << ',' << count;
    }
    out << '\n';
  }
}

void write_csv_file(const RunResult& result, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) { write_csv(result, out); });
}

RunResult read_csv(std::istream& in) {
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.empty()) corrupt("empty");
  if (text.back() != '\n') corrupt("truncated (no final newline)");
  std::istringstream lines(text);
  std::string line;
  std::map<std::string, std::string> header;
  std::string columns;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] != '#') {
      columns = line;
      break;
    }
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) continue;  // the title line
    header[line.substr(2, eq - 2)] = line.substr(eq + 3);
  }
  auto field = [&](const std::string& key) -> const std::string& {
    const auto it = header.find(key);
    if (it == header.end()) corrupt("missing header '" + key + "'");
    return it->second;
  };
  RunResult r;
  Parameters& p = r.parameters;
  for (const ParameterInfo& info : parameter_table()) {
    if (info.omitted_at_default && !header.contains(std::string(info.name)))
      continue;  // written without the row, or at its default: p keeps the default
    try {
      parse_value(p, info, field(std::string(info.name)));
    } catch (const std::invalid_argument& e) {
      corrupt(e.what());
    }
  }
  r.version = field("version");
  const auto stop = parse_stop_reason(field("stop_reason"));
  if (!stop) corrupt("stop_reason '" + field("stop_reason") + "'");
  r.stop_reason = *stop;
  r.collisions = parse_uint(field("collisions"), "collisions");
  r.events = parse_uint(field("events"), "events");
  const std::uint64_t rows = parse_uint(field("rows"), "rows");

  const std::string expected =
      std::string(k_base_columns) + (p.contact_statistics ? contact_columns() : "");
  if (columns != expected) corrupt("column line '" + columns + "'");
  const std::size_t width = split(expected, ',').size();
  while (std::getline(lines, line)) {
    const auto f = split(line, ',');
    if (f.size() != width)
      corrupt("row " + std::to_string(r.samples.size() + 1) + " has " + std::to_string(f.size()) +
              " fields");
    Sample s;
    s.t = parse_double(f[0], "t");
    s.temperature = parse_double(f[1], "T");
    s.a2 = parse_double(f[2], "a2");
    s.collisions = parse_uint(f[3], "collisions");
    s.events = parse_uint(f[4], "events");
    s.velocity_mode = parse_double(f[5], "velocity_mode");
    s.density_mode = parse_double(f[6], "density_mode");
    if (p.contact_statistics) {
      s.contacts.count = parse_uint(f[7], "contacts");
      s.contacts.sum_c1e_c2e = parse_double(f[8], "sum_c1e_c2e");
      s.contacts.sum_c1_dot_c2 = parse_double(f[9], "sum_c1_dot_c2");
      s.contacts.sum_gn2 = parse_double(f[10], "sum_gn2");
      s.contacts.sum_abs_gn = parse_double(f[11], "sum_abs_gn");
      s.contacts.sum_g2 = parse_double(f[12], "sum_g2");
      for (std::size_t b = 0; b < s.contacts.impact_histogram.size(); ++b)
        s.contacts.impact_histogram[b] =
            parse_uint(f[k_first_impact_column + b], "impact_" + std::to_string(b));
    }
    r.samples.push_back(s);
  }
  if (r.samples.size() != rows)
    corrupt("truncated: " + std::to_string(r.samples.size()) + " rows of " + std::to_string(rows));
  return r;
}

RunResult read_csv_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  try {
    return read_csv(in);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

void write_snapshot_csv(const RunResult& r, std::size_t index, std::ostream& out) {
  const Snapshot& snapshot = r.snapshots.at(index);
  const int dimension = r.parameters.dimension;
  out << "# molchaos snapshot " << index << " of the run below (sigma = m = 1, T0 = 1)\n"
      << "# version = " << r.version << "\n";
  write_parameter_lines(r.parameters, out);
  out << "# t = " << round_trip_text(snapshot.t) << "\n# box = " << round_trip_text(snapshot.box)
      << "\n# collisions = " << snapshot.collisions << "\n";
  out << (dimension == 2 ? "x,y,vx,vy\n" : "x,y,z,vx,vy,vz\n");
  const std::size_t n = snapshot.positions.size() / static_cast<std::size_t>(dimension);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < dimension; ++a)
      out << round_trip_text(snapshot.positions[i * dimension + a]) << ',';
    for (int a = 0; a < dimension; ++a)
      out << round_trip_text(snapshot.velocities[i * dimension + a])
          << (a + 1 < dimension ? ',' : '\n');
  }
}

}  // namespace molchaos::sim
