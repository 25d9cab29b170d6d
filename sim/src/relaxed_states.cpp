#include "molchaos/sim/relaxed_states.hpp"

#include <atomic>
#include <deque>
#include <map>
#include <mutex>

#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::sim {
namespace {

struct Store {
  std::mutex mutex;
  std::map<std::string, std::shared_ptr<const std::string>> states;
  std::deque<std::string> order;  ///< keys, oldest first
  std::size_t bytes = 0;
};

Store& store() {
  static Store s;
  return s;
}

std::atomic<bool> g_sharing{true};

}  // namespace

std::string relaxed_state_key(const Parameters& p, const std::string& engine_layout) {
  std::string key = engine_layout;
  for (const char* name :
       {"dimension", "particles", "density", "seed", "relax_collisions_per_particle",
        "max_collisions"}) {  // max_collisions bounds the events, relaxation's included
    key += ' ';
    key += format_value(p, *find_parameter(name));
  }
  return key;
}

std::shared_ptr<const std::string> find_relaxed_state(const std::string& key) {
  if (!g_sharing.load()) return nullptr;
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  const auto it = s.states.find(key);
  return it == s.states.end() ? nullptr : it->second;
}

void keep_relaxed_state(const std::string& key, std::string state) {
  if (!g_sharing.load() || state.size() > k_largest_kept_state) return;
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  if (s.states.contains(key)) return;  // another thread relaxed the same state meanwhile
  s.bytes += state.size();
  s.states.emplace(key, std::make_shared<const std::string>(std::move(state)));
  s.order.push_back(key);
  while (s.bytes > k_kept_bytes && !s.order.empty()) {
    const auto it = s.states.find(s.order.front());
    s.bytes -= it->second->size();
    s.states.erase(it);
    s.order.pop_front();
  }
}

void share_relaxed_states(bool on) { g_sharing.store(on); }
bool relaxed_states_shared() { return g_sharing.load(); }

void clear_relaxed_states() {
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  s.states.clear();
  s.order.clear();
  s.bytes = 0;
}

std::size_t kept_relaxed_states() {
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  return s.states.size();
}

}  // namespace molchaos::sim
