#include "write_fault_injection.hpp"

#include <mpi.h>

#include <cstdlib>
#include <string>

#include "catena/core/error.hpp"

namespace catena::io {
namespace {

constexpr const char* variable = "CATENA_FAULT_INJECT_WRITE";

struct InjectionState {
  std::optional<WriteFault> fault;
  std::int64_t matching_calls = 0;
};

// Read from the environment at the first write call (MPI is initialised by then).
InjectionState& state() {
  static InjectionState injection = [] {
    InjectionState initial;
    if (const char* text = std::getenv(variable); text != nullptr && *text != '\0')
      initial.fault = parse_write_fault(text);
    return initial;
  }();
  return injection;
}

[[noreturn]] void reject(std::string_view text, const std::string& why) {
  throw Error(std::string(variable) + "='" + std::string(text) + "': " + why +
              "; accepted: rank=R,call=N[,at=TEXT] (R >= 0, N >= 1)");
}

std::int64_t parse_integer(std::string_view text, std::string_view value, std::int64_t minimum) {
  const std::string digits(value);
  char* end = nullptr;
  const long long number = std::strtoll(digits.c_str(), &end, 10);
  if (digits.empty() || *end != '\0' || number < minimum)
    reject(text, "'" + digits + "' is not an integer >= " + std::to_string(minimum));
  return number;
}

}  // namespace

WriteFault parse_write_fault(std::string_view text) {
  WriteFault fault;
  bool has_rank = false, has_call = false;
  std::string_view rest = text;
  while (!rest.empty()) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    const std::size_t equals = item.find('=');
    if (equals == std::string_view::npos)
      reject(text, "'" + std::string(item) + "' is not KEY=VALUE");
    const std::string_view key = item.substr(0, equals), value = item.substr(equals + 1);
    if (key == "rank") {
      fault.rank = static_cast<int>(parse_integer(text, value, 0));
      has_rank = true;
    } else if (key == "call") {
      fault.call = parse_integer(text, value, 1);
      has_call = true;
    } else if (key == "at") {
      fault.at = std::string(value);
    } else {
      reject(text, "unknown key '" + std::string(key) + "'");
    }
  }
  if (!has_rank || !has_call) reject(text, "rank and call are required");
  return fault;
}

void set_write_fault(std::optional<WriteFault> fault) {
  state() = InjectionState{std::move(fault), 0};
}

bool write_fault_injected(std::string_view call, std::string_view file, std::string_view object) {
  InjectionState& injection = state();
  if (!injection.fault) return false;
  if (call != "H5Dwrite" && call != "H5Fflush" && call != "H5Fclose") return false;
  const WriteFault& fault = *injection.fault;
  int world_rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &world_rank);
  if (world_rank != fault.rank) return false;
  if (!fault.at.empty() && file.find(fault.at) == std::string_view::npos &&
      object.find(fault.at) == std::string_view::npos)
    return false;
  return ++injection.matching_calls == fault.call;
}

}  // namespace catena::io
