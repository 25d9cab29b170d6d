// Byte layout of the protocol messages: fixed-width fields copied with memcpy, strings and
// vectors prefixed by their length.
#include "molchaos/mpi/wire.hpp"

#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "molchaos/sim/parameter_table.hpp"

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

// Every parameter in table order, in its own type; a list is its length then its elements.
std::string encode(const JobMessage& job) {
  Writer w;
  w.put(job.index);
  for (const sim::ParameterInfo& info : sim::parameter_table())
    std::visit(
        [&](auto member) {
          const auto& value = job.parameters.*member;
          using T = std::remove_cvref_t<decltype(value)>;
          if constexpr (std::is_same_v<T, bool>) {
            w.put(static_cast<std::uint8_t>(value ? 1 : 0));
          } else if constexpr (std::is_enum_v<T>) {  // a choice: its index
            w.put(static_cast<std::int32_t>(sim::choice_index(job.parameters, info)));
          } else if constexpr (std::is_same_v<T, std::vector<double>>) {
            w.put<std::uint64_t>(value.size());
            for (double x : value) w.put(x);
          } else {
            w.put(value);
          }
        },
        info.field);
  return w.take();
}

JobMessage decode_job(std::string_view bytes) {
  Reader r(bytes);
  JobMessage job;
  job.index = r.get<std::uint64_t>();
  for (const sim::ParameterInfo& info : sim::parameter_table())
    std::visit(
        [&](auto member) {
          auto& value = job.parameters.*member;
          using T = std::remove_cvref_t<decltype(value)>;
          if constexpr (std::is_same_v<T, bool>) {
            value = r.get<std::uint8_t>() != 0;
          } else if constexpr (std::is_enum_v<T>) {
            const auto index = r.get<std::int32_t>();
            if (index < 0 || static_cast<std::size_t>(index) >= info.choices.size())
              throw std::runtime_error("MPI message: unknown choice of " + std::string(info.name));
            value = static_cast<T>(index);
          } else if constexpr (std::is_same_v<T, std::vector<double>>) {
            const auto count = r.get<std::uint64_t>();
            if (count > bytes.size() / sizeof(double))
              throw std::runtime_error("MPI message: bad length of " + std::string(info.name));
            value.resize(count);
            for (double& x : value) x = r.get<double>();
          } else {
            value = r.get<T>();
          }
        },
        info.field);
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
