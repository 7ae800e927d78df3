#include "run_export.hpp"

#include <cstdio>
#include <string>
#include <system_error>

#include "catena/io/atomic_file.hpp"
#include "catena/io/output_error.hpp"

namespace catena::app {
namespace {

std::string ten_digit_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", x);
  return buffer;
}

// A CSV field: quoted when it holds a separator, a quote or a line break.
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

void write_contact_csv(const RunEvaluation& ev, const std::filesystem::path& path) {
  std::string out = "t_s";
  for (const PantographEvaluation& e : ev.pantographs)
    for (const char* column : {"_position_m", "_force_N", "_force_filtered_N"}) {
      out += ',';
      out += field(e.pantograph->name + column);
    }
  out += '\n';
  const std::size_t n = ev.run.n_samples;
  for (std::size_t k = 0; k < n; ++k) {
    out += ten_digit_number(ev.run.time[k]);
    for (const PantographEvaluation& e : ev.pantographs) {
      out += ',';
      out += ten_digit_number(e.pantograph->position[k]);
      out += ',';
      out += ten_digit_number(e.pantograph->force[k]);
      out += ',';
      out += ten_digit_number(e.filtered_force[k]);
    }
    out += '\n';
  }
  io::write_file_atomically(path, out);
}

void write_statistics_csv(const RunEvaluation& ev, const std::filesystem::path& path) {
  std::string out =
      "pantograph,speed_kmh,section_start_m,section_end_m,complete,samples,mean_N,std_N,"
      "stat_max_N,stat_min_N,max_N,min_N,contact_loss_percent,max_uplift_at_support_mm";
  const bool ranges = !ev.ranges.empty();
  const char* statistics[] = {"mean",
                              "std",
                              "stat_max",
                              "stat_min",
                              "max",
                              "min",
                              "max_uplift_at_support",
                              "contact_loss_percent"};
  if (ranges) {
    out += ",acceptance,in_range,of";
    for (const char* s : statistics) out += std::string(",") + s + "_in_range";
  }
  out += '\n';
  for (const PantographEvaluation& e : ev.pantographs) {
    // The section evaluated; empty cells where the pantograph covered none of it.
    const std::string start = e.statistics ? ten_digit_number(e.section.x_start) : "";
    const std::string end = e.statistics ? ten_digit_number(e.section.x_end) : "";
    out += field(e.pantograph->name) + ',' + ten_digit_number(e.pantograph->speed * kmh_per_ms) +
           ',' + start + ',' + end + ',' + (ev.finished ? "1" : "0") + ',';
    if (e.statistics) {
      const post::ContactStatistics& s = *e.statistics;
      out += std::to_string(s.n_samples);
      for (double x : {s.mean, s.standard_deviation, s.statistical_max, s.statistical_min, s.max,
                       s.min, s.contact_loss_percent})
        out += ',' + ten_digit_number(x);
      out +=
          ',' + (s.max_uplift_at_support ? ten_digit_number(1e3 * *s.max_uplift_at_support) : "");
    } else {
      out += "0,,,,,,,,";
    }
    if (ranges) {
      if (e.acceptance) {
        out += ',' + ev.ranges + ',' + std::to_string(checks_passed(*e.acceptance)) + ',' +
               std::to_string(e.acceptance->size());
        for (const char* s : statistics)
          for (const post::AcceptanceCheck& c : *e.acceptance)
            if (c.statistic == s) out += c.pass ? ",1" : ",0";
      } else {
        out += ",,,";  // another speed, or not in the section
        for (std::size_t i = 0; i < std::size(statistics); ++i) out += ',';
      }
    }
    out += '\n';
  }
  io::write_file_atomically(path, out);
}

void create_parent_directory(const std::filesystem::path& file) {
  const std::filesystem::path directory = file.parent_path();
  if (directory.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw OutputError("cannot create the directory '" + directory.string() + "' for " +
                      file.filename().string() + ": " + error.message());
}

std::string default_prefix(const std::string& output_file) {
  std::filesystem::path p(output_file);
  if (p.extension() == ".h5" || p.extension() == ".hdf5") p.replace_extension();
  return p.string();
}

}  // namespace catena::app
