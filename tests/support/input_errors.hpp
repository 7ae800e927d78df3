#pragma once
// Checks of bad-input messages (error tier 2, core/error.hpp) for tests that vary a good
// scene with --set overrides: the message must name the file and say what is wrong.
// Header-only so that test support needs no layer above core.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::test {

// The message of the InputError that read() throws; a test failure and "" if none.
template <class Read>
std::string input_error_message(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

struct InputErrorCase {
  std::vector<std::string> overrides;
  std::vector<std::string> fragments;  // each must appear in the message
};

// For every case: read_with(overrides) throws an InputError whose message contains
// `file_label` and every fragment.
template <class ReadWith>
void expect_input_errors(ReadWith&& read_with, const std::string& file_label,
                         const std::vector<InputErrorCase>& cases) {
  for (const InputErrorCase& c : cases) {
    const std::string message = input_error_message([&] { read_with(c.overrides); });
    EXPECT_NE(message.find(file_label), std::string::npos) << message;
    for (const std::string& fragment : c.fragments)
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "--set " << (c.overrides.empty() ? std::string() : c.overrides.back()) << ": '"
          << fragment << "' not in: " << message;
  }
}

}  // namespace catena::test
