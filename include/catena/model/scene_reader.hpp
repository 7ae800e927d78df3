#pragma once
// Scene reader: YAML text (format and every key: docs/scene.md) → a validated Model.
//
// Parallel use: the app reads the file on rank 0 only (read_scene_file), runs
// check_scene_text there,
// broadcasts the text (catena::broadcast_string) and calls parse_scene on every rank.
// Parsing is deterministic, so every rank builds the same Model or throws the same
// InputError. Nothing here communicates.
//
// Every problem with the user's input throws catena::InputError naming the file, the
// 1-based line, the dotted key ("lines[0].elements", "sections.cw.EA"), the offending
// value and what is accepted (error tier 2, core/error.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "catena/model/memory_estimate.hpp"
#include "catena/model/model.hpp"

namespace catena::model {

inline constexpr std::size_t max_scene_bytes = std::size_t{64} << 20;  // 64 MiB
inline constexpr std::size_t max_scene_line_bytes = 65536;

// Not collective. Cheap checks before YAML parsing, so that a wrong file gives a clear
// message instead of a parser error: at most max_scene_bytes, text (no NUL bytes, valid
// UTF-8; else "binary"), no line longer than max_scene_line_bytes (the message names the
// line and its length), not empty or only comments ("scene is empty").
void check_scene_text(const std::string& text, const std::string& file_label);

// Not collective. Parses scene text; `file_label` names it in messages. `overrides` are
// "dotted.path=value" strings (the app's --set) applied to the YAML tree before
// validation, so overridden values are validated like the file's own and messages about
// them name the override. The value is YAML ("7", "x.h5", "[0, 0, -5]"). Runs
// check_scene_text first. Sets Model::source_file = file_label and Model::source_text
// (the text itself if there are no overrides; otherwise the tree after overrides,
// re-emitted, headed by comments listing the overrides — a complete scene that reproduces
// the run, at the cost of the original comments). An active `budget` refuses a scene whose
// run's estimated memory (memory_estimate.hpp) exceeds it, the lines before they are
// generated. Throws InputError.
Model parse_scene(const std::string& text, const std::string& file_label,
                  const std::vector<std::string>& overrides = {}, const MemoryBudget& budget = {});

// Not collective. The text of the scene file at `path`, which must exist and be a readable
// regular file (not a directory, a device or a pipe, which would be read without end or
// block) of at most max_scene_bytes; else an InputError naming the path and what it is.
std::string read_scene_file(const std::string& path);

// Not collective. read_scene_file, then parse_scene with `path` as the label. Throws
// InputError.
Model read_scene(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace catena::model
