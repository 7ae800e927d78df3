// The "Advice:" part of the `catena check` summary: before a run, from the scene alone,
// which structure model (analysis.structure: nonlinear, linear, modal) the pantograph runs
// can use, and whether the step resolves the contact. The rules and the runs that calibrate
// them: docs/accuracy.md, "Choosing a structure model before the run".
#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "catena/model/contact_mode.hpp"
#include "number_format.hpp"
#include "summary_table.hpp"

namespace catena::model::detail {
namespace {

// The speed ratios v/c (c = √(T/μ), the contact wire's transverse wave speed) up to which
// the reduced models were measured to keep σ within 1 % of the nonlinear run and loss of
// contact the same, on EN 50318's line with one pantograph at 200 to 380 km/h
// (docs/accuracy.md): the linear structure held at 350 km/h (0.80: σ −0.13 %, the same
// 0.324 % loss of contact) and not at 380 (0.87: 1.54 % loss against 1.45 %); the modal
// model (100 Hz) held at 275 km/h (0.63: σ −0.08 %) and not at 300 (0.685: σ +1.7 %).
// Beyond them the advice is the nonlinear structure.
constexpr double kLinearMeasuredRatio = 0.80;
constexpr double kModalMeasuredRatio = 0.63;
// EN 50119's design rule: the operating speed at most 70 % of the contact wire's wave speed.
constexpr double kEn50119Ratio = 0.70;

struct WireWave {
  double tension = 0.0, mass_per_length = 0.0;
  double speed() const { return std::sqrt(tension / mass_per_length); }
};

WireWave contact_wire_wave(const Model& m) {
  const CatenaryWire& w = m.catenary->contact_wire;
  const ElementDesc& e = m.elements[static_cast<std::size_t>(w.elements.front())];
  return {w.tension, std::get<CableProps>(*e.props).mass_per_length};
}

// Thresholds print whole ("80 %"), a scene's ratio to a tenth ("80.1 %"), so that a ratio
// just above a threshold does not print as the threshold itself beside "above".
std::string percent(double ratio) { return cat(format_number(std::round(100.0 * ratio)), " %"); }
std::string ratio_text(double ratio) {
  return cat(format_number(std::round(1000.0 * ratio) / 10.0), " %");
}

// Pantographs running behind another on the same path, in its waves: "'trailing' 200 m
// behind 'leading'", one entry per follower (the nearest pantograph ahead of it).
std::vector<std::string> followers(const Model& m) {
  std::vector<std::string> out;
  for (const MovingContact& c : m.contacts) {
    const MovingContact* ahead = nullptr;
    for (const MovingContact& o : m.contacts)
      // Moving the same way at the same speed (to round-off: speed and speed_kmh), ahead.
      // (either direction: "ahead" is along the travel, forward or backward).
      if (&o != &c && o.path == c.path && c.speed != 0.0 &&
          std::abs(o.speed - c.speed) <= 1e-9 * std::abs(c.speed) &&
          (o.start - c.start) * c.speed > 0.0 &&
          (!ahead || std::abs(o.start - c.start) < std::abs(ahead->start - c.start)))
        ahead = &o;
    if (ahead)
      out.push_back(cat("'", c.name, "' ", format_number(std::abs(ahead->start - c.start)),
                        " m behind '", ahead->name, "'"));
  }
  return out;
}

// The static pull of each dropper on the contact wire, estimated as the wire's weight
// from half-way to the dropper or support before it to half-way to the one after it
// (clamp masses and the messenger's share left out): its smallest and largest value, N.
std::pair<double, double> dropper_pull(const Model& m, double mass_per_length) {
  std::vector<double> x = m.catenary->support_x;
  std::vector<bool> is_dropper(x.size(), false);
  for (const CatenaryDropper& d : m.catenary->droppers) {
    x.push_back(m.nodes[static_cast<std::size_t>(d.contact_node)].position.x());
    is_dropper.push_back(true);
  }
  std::vector<std::size_t> order(x.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  const double weight = mass_per_length * std::abs(m.gravity.z());
  double low = 0.0, high = 0.0;
  bool any = false;
  for (std::size_t k = 1; k + 1 < order.size(); ++k) {
    if (!is_dropper[order[k]]) continue;
    const double pull = weight * 0.5 * (x[order[k + 1]] - x[order[k - 1]]);
    low = any ? std::min(low, pull) : pull;
    high = any ? std::max(high, pull) : pull;
    any = true;
  }
  return {low, high};
}

}  // namespace

void advise_structure(const Model& m, SummaryTable& t) {
  if (m.analysis != AnalysisType::dynamic || !m.catenary || m.contacts.empty() ||
      m.catenary->contact_wire.elements.empty())
    return;
  const WireWave wave = contact_wire_wave(m);
  t.heading("Advice (from the scene alone; docs/accuracy.md, \"Choosing a structure model\"):");
  double worst_ratio = 0.0;
  for (const MovingContact& c : m.contacts) {
    const double ratio = std::abs(c.speed) / wave.speed();
    worst_ratio = std::max(worst_ratio, ratio);
    t.row(c.name, cat(format_number(std::abs(c.speed) * 3.6), " km/h is ", ratio_text(ratio),
                      " of the contact wire's wave speed sqrt(T/mu) = ",
                      format_number(wave.speed() * 3.6), " km/h",
                      ratio > kEn50119Ratio ? " (above EN 50119's 70 %: expect large uplift "
                                              "and loss of contact)"
                                            : " (EN 50119's design limit: 70 %)"));
  }
  const std::vector<std::string> wakes = followers(m);
  for (const std::string& w : wakes)
    t.row("in a wake", cat(w, ": it runs into the waves the first one leaves"));

  // The structure model: the cheapest one measured to hold on such a run.
  std::string verdict;
  if (!wakes.empty())
    verdict =
        cat("nonlinear: a pantograph in another's wake (the linear structure measured "
            "0 % loss of contact where the nonlinear one lost 0.139 %)");
  else if (worst_ratio > kLinearMeasuredRatio)
    verdict = cat("nonlinear: above ", percent(kLinearMeasuredRatio),
                  " of the wave speed the linear structure's loss of contact was measured to "
                  "differ (87 %: 1.54 % against 1.45 %)");
  else if (worst_ratio > kModalMeasuredRatio)
    verdict = cat("linear (σ within 1 % of the nonlinear run measured up to ",
                  percent(kLinearMeasuredRatio), " of the wave speed); not modal: its σ was ",
                  "measured 1.7 % high at 68.5 % (300 km/h), within 1 % up to ",
                  percent(kModalMeasuredRatio));
  else
    verdict = cat("modal or linear (σ within 1 % of the nonlinear run measured up to ",
                  percent(kModalMeasuredRatio), " and ", percent(kLinearMeasuredRatio),
                  " of the wave speed)");
  t.row("structure", verdict);

  if (!m.catenary->droppers.empty()) {
    const auto [low, high] = dropper_pull(m, wave.mass_per_length);
    double uplift = 0.0;
    for (const MovingContact& c : m.contacts)
      uplift = std::max(uplift, c.static_force + c.aerodynamic_coefficient * c.speed * c.speed);
    t.row("droppers",
          cat("static pull on the contact wire about ", format_number(std::round(low)), " to ",
              format_number(std::round(high)), " N each (the wire's weight between them); uplift ",
              format_number(uplift), " N",
              uplift > low ? ": the droppers next to a pantograph slacken as it passes; every "
                             "structure model keeps their tension-only switch"
                           : ": below every dropper's pull"));
  }

  const double dt = m.dynamic_options.integrator.dt;
  for (const MovingContact& c : m.contacts) {
    if (c.bilateral) {
      t.row("contact mode", cat("'", c.name, "': none (bilateral: no contact spring)"));
      continue;
    }
    const ContactMode mode = contact_mode(m, c);
    const double dt_omega = mode.omega * dt;
    // A multistep method's damping hides an under-stepped mode well below 1 (contact_mode.hpp).
    const double limit = multistep_contact_limit(m);
    const std::string resolution =
        dt_omega > limit  ? cat(": above the ", format_number(limit),
                                " a multistep method needs (its damping smooths the force "
                                 "into a wrong one): see the warning below")
        : dt_omega <= 1.0 ? std::string(": resolved")
                          : std::string(
                                ": not resolved by the step (HHT chattered at 2.0, "
                                "Radau IIA held at 1.6): watch the run's "
                                "contact-resolution warning");
    t.row("contact mode",
          cat("'", c.name, "': ", format_number(mode.omega), " rad/s (head on ",
              format_number(c.stiffness), " N/m against ", format_number(mode.element_length),
              " m of wire), dt*omega = ", format_number(dt_omega), resolution));
  }
}

}  // namespace catena::model::detail
