// Text checks shared by the tests.
#pragma once

#include <functional>
#include <string>

namespace swarm::test {

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// What `f` throws as an E (its what()), or `none` when it throws no E: the whole message, for
// tests that check an error names its field or file.
//   EXPECT_EQ(error_of<ConfigError>([&] { load(path); }), "t.pbtxt:3:19: ...");
template <class E>
std::string error_of(const std::function<void()>& f, const std::string& none = "") {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return none;
}

}  // namespace swarm::test
