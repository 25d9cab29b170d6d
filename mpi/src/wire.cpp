// Byte layout of the protocol messages: fixed-width fields copied with memcpy, strings and
// vectors prefixed by their length.
#include "molchaos/mpi/wire.hpp"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace molchaos::mpi {
namespace {

class Writer {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes_.append(raw, sizeof(T));
  }
  void put_text(std::string_view text) {
    put<std::uint64_t>(text.size());
    bytes_.append(text);
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string get_text() {
    const auto size = get<std::uint64_t>();
    need(size);
    std::string text(bytes_.substr(at_, size));
    at_ += size;
    return text;
  }
  void expect_end() const {
    if (at_ != bytes_.size()) throw std::runtime_error("MPI message: trailing bytes");
  }

 private:
  void need(std::uint64_t count) const {
    if (count > bytes_.size() - at_) throw std::runtime_error("MPI message: truncated");
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::string encode(const JobMessage& job) {
  const sim::Parameters& p = job.parameters;
  Writer w;
  w.put(job.index);
  w.put(p.dimension);
  w.put(p.particles);
  w.put(p.density);
  w.put(p.restitution);
  w.put(static_cast<std::int32_t>(p.randomize));
  w.put(p.seed);
  w.put(p.t_end);
  w.put(p.relax_collisions_per_particle);
  w.put(p.tc);
  w.put(p.samples_per_decade);
  w.put(p.t_first_sample);
  w.put(static_cast<std::uint8_t>(p.contact_statistics ? 1 : 0));
  w.put<std::uint64_t>(p.snapshot_times.size());
  for (double t : p.snapshot_times) w.put(t);
  w.put(p.max_collisions);
  w.put(p.min_temperature);
  return w.take();
}

JobMessage decode_job(std::string_view bytes) {
  Reader r(bytes);
  JobMessage job;
  sim::Parameters& p = job.parameters;
  job.index = r.get<std::uint64_t>();
  p.dimension = r.get<int>();
  p.particles = r.get<std::int64_t>();
  p.density = r.get<double>();
  p.restitution = r.get<double>();
  const auto mode = r.get<std::int32_t>();
  if (mode < 0 || mode > static_cast<std::int32_t>(sim::Randomization::flux))
    throw std::runtime_error("MPI message: unknown randomization mode");
  p.randomize = static_cast<sim::Randomization>(mode);
  p.seed = r.get<std::uint64_t>();
  p.t_end = r.get<double>();
  p.relax_collisions_per_particle = r.get<double>();
  p.tc = r.get<double>();
  p.samples_per_decade = r.get<int>();
  p.t_first_sample = r.get<double>();
  p.contact_statistics = r.get<std::uint8_t>() != 0;
  const auto snapshots = r.get<std::uint64_t>();
  if (snapshots > bytes.size() / sizeof(double))
    throw std::runtime_error("MPI message: bad snapshot count");
  p.snapshot_times.resize(snapshots);
  for (double& t : p.snapshot_times) t = r.get<double>();
  p.max_collisions = r.get<std::uint64_t>();
  p.min_temperature = r.get<double>();
  r.expect_end();
  return job;
}

std::string encode(const ResultMessage& result) {
  Writer w;
  w.put(result.index);
  w.put(static_cast<std::uint8_t>(result.ok ? 1 : 0));
  w.put_text(result.text);
  return w.take();
}

ResultMessage decode_result(std::string_view bytes) {
  Reader r(bytes);
  ResultMessage result;
  result.index = r.get<std::uint64_t>();
  result.ok = r.get<std::uint8_t>() != 0;
  result.text = r.get_text();
  r.expect_end();
  return result;
}

}  // namespace molchaos::mpi
