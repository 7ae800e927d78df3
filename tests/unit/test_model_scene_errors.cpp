// The scene reader rejects malformed scenes with specific messages. Every file in
// tests/data/bad_scenes/ is one malformed scene whose header comments say what the error
// must contain, so adding a case means adding a file:
//   # expect: <text>   every such text must appear in the message (what())
//   # set: <override>  passed to read_scene as a --set override (in order)
//   ... # <-- error    the 1-based line the error must point at (InputError::where().line)
// Each message must also name the file. Cases a text file cannot hold (binary data, a
// 10 MB line, missing files) are at the end.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/model/scene_reader.hpp"

namespace {

namespace fs = std::filesystem;
using catena::InputError;
using catena::model::check_scene_text;
using catena::model::parse_scene;
using catena::model::read_scene;

const fs::path bad_scene_dir = fs::path(CATENA_TEST_DATA) / "bad_scenes";

// What a bad scene's header comments ask for.
struct Expectation {
  std::vector<std::string> fragments;
  std::vector<std::string> overrides;
  int line = 0;  // 0: not checked
};

Expectation read_expectation(const fs::path& file) {
  Expectation e;
  std::ifstream in(file);
  std::string text;
  int number = 0;
  const auto directive = [&](const std::string& prefix, std::vector<std::string>& into) {
    if (text.rfind(prefix, 0) == 0) into.push_back(text.substr(prefix.size()));
  };
  while (std::getline(in, text)) {
    ++number;
    directive("# expect: ", e.fragments);
    directive("# set: ", e.overrides);
    if (text.find("# <-- error") != std::string::npos) e.line = number;
  }
  return e;
}

std::vector<std::string> bad_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(bad_scene_dir))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Runs `read` and returns the InputError it must throw.
template <class Read>
InputError expect_input_error(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError({}, "");
}

class BadScene : public ::testing::TestWithParam<std::string> {};

TEST_P(BadScene, ThrowsInputErrorNamingFileKeyValueAndAcceptedRange) {
  const fs::path file = bad_scene_dir / (GetParam() + ".yaml");
  const Expectation expected = read_expectation(file);
  ASSERT_FALSE(expected.fragments.empty()) << file << " has no '# expect:' line";

  const InputError error =
      expect_input_error([&] { read_scene(file.string(), expected.overrides); });
  const std::string message = error.what();
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_EQ(error.where().file, file.string());
  for (const std::string& fragment : expected.fragments)
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "missing '" << fragment << "' in: " << message;
  if (expected.line > 0) {
    EXPECT_EQ(error.where().line, expected.line) << message;
  }
}

// gtest's name generator parameter is itself called `info`; ours must differ (-Wshadow).
std::string scene_name(const ::testing::TestParamInfo<std::string>& scene) { return scene.param; }

INSTANTIATE_TEST_SUITE_P(Files, BadScene, ::testing::ValuesIn(bad_scene_names()), scene_name);

TEST(BadScenes, CoverAtLeastTwentyFiveCases) { EXPECT_GE(bad_scene_names().size(), 25u); }

// --- cases generated here rather than stored ---------------------------------------------

TEST(SceneText, EmptyFileIsEmptyScene) {
  const InputError e = expect_input_error([] { parse_scene("", "empty.yaml"); });
  EXPECT_NE(std::string(e.what()).find("empty.yaml"), std::string::npos);
  EXPECT_NE(std::string(e.what()).find("scene is empty"), std::string::npos);
}

TEST(SceneText, BinaryGarbageIsRejectedAsBinary) {
  std::string garbage = "sections:\n  cw: {type: cable}\n";
  for (int i = 0; i < 256; ++i) garbage += static_cast<char>((i * 37 + 11) % 256);
  const InputError e = expect_input_error([&] { parse_scene(garbage, "garbage.bin"); });
  EXPECT_NE(std::string(e.what()).find("garbage.bin"), std::string::npos);
  EXPECT_NE(std::string(e.what()).find("binary"), std::string::npos) << e.what();
}

TEST(SceneText, InvalidUtf8WithoutNulIsBinary) {
  const std::string latin1 = "name: caf\xE9\n";  // ISO-8859-1 é, not UTF-8
  const InputError e = expect_input_error([&] { check_scene_text(latin1, "latin1.yaml"); });
  EXPECT_NE(std::string(e.what()).find("not valid UTF-8 at line 1"), std::string::npos) << e.what();
}

TEST(SceneText, TenMegabyteLineNamesLineAndLength) {
  const std::string text = "name: x\n# " + std::string(10'000'000, 'a') + "\n";
  const InputError e = expect_input_error([&] { parse_scene(text, "long.yaml"); });
  const std::string message = e.what();
  EXPECT_EQ(e.where().line, 2);
  EXPECT_NE(message.find("long.yaml:2"), std::string::npos) << message.substr(0, 200);
  EXPECT_NE(message.find("line 2 is 10000002 bytes long"), std::string::npos);
  EXPECT_NE(message.find("at most 65536"), std::string::npos);
}

TEST(SceneText, MoreThan64MiBIsRejected) {
  const std::string text(catena::model::max_scene_bytes + 1, '\n');
  const InputError e = expect_input_error([&] { check_scene_text(text, "huge.yaml"); });
  EXPECT_NE(std::string(e.what()).find("at most 67108864 bytes (64 MiB)"), std::string::npos);
}

TEST(SceneText, DocumentMarkersAndCommentsAloneAreEmpty) {
  EXPECT_THROW(check_scene_text("---  # start\n# nothing\n...\n", "markers.yaml"), InputError);
  EXPECT_NO_THROW(check_scene_text("\xEF\xBB\xBF--- {name: x}\n", "inline.yaml"));
  EXPECT_NO_THROW(check_scene_text("name: caf\xC3\xA9  # UTF-8\n", "utf8.yaml"));
}

TEST(Suggestions, NothingCloseGivesNoSuggestion) {
  const std::string text = "zzz: 1\n";
  const InputError e = expect_input_error([&] { parse_scene(text, "far.yaml"); });
  const std::string message = e.what();
  EXPECT_NE(message.find("unknown key 'zzz'; accepted keys: name,"), std::string::npos) << message;
  EXPECT_EQ(message.find("did you mean"), std::string::npos) << message;
}

TEST(SceneFile, MissingFileIsNamed) {
  const std::string path = (bad_scene_dir / "no_such_scene.yaml").string();
  const InputError e = expect_input_error([&] { read_scene(path); });
  EXPECT_NE(std::string(e.what()).find(path + ": cannot read scene: no such file"),
            std::string::npos)
      << e.what();
}

TEST(SceneFile, DirectoryIsNotAScene) {
  const InputError e = expect_input_error([] { read_scene(bad_scene_dir.string()); });
  EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
}

TEST(SceneFile, EmptyFileOnDiskIsEmptyScene) {
  const fs::path path = fs::temp_directory_path() / "catena_test_empty_scene.yaml";
  std::ofstream(path).close();
  const InputError e = expect_input_error([&] { read_scene(path.string()); });
  fs::remove(path);
  EXPECT_NE(std::string(e.what()).find("scene is empty"), std::string::npos) << e.what();
}

}  // namespace
