// An environment variable set (or unset) for one test's scope and given back its old value,
// or unset again, at scope exit: the tests share one process, and a variable left behind
// (SVGMOTION_CACHE_DIR, SVGMOTION_COMPILE_CHILD) would change what every later test does.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>

namespace svgm::test {

class ScopedEnv {
 public:
  // Sets NAME to VALUE; nullopt unsets it.
  ScopedEnv(std::string name, const std::optional<std::string>& value) : name_(std::move(name)) {
    if (const char* old = std::getenv(name_.c_str())) old_ = old;
    set(value);
  }
  ~ScopedEnv() { set(old_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

  void set(const std::optional<std::string>& value) {
    if (value) setenv(name_.c_str(), value->c_str(), 1);
    else unsetenv(name_.c_str());
  }

 private:
  std::string name_;
  std::optional<std::string> old_;
};

}  // namespace svgm::test
