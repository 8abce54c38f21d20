#pragma once
// A long set-up phase (grains settling before a run) as the user sees it: it reports how far it
// has come, and it stops when the user asks (Ctrl-C or SIGTERM) by throwing Interrupted. The app
// provides the monitor; the methods only call it.
#include <cstddef>
#include <string>

namespace partimix {

class PhaseMonitor {
 public:
  virtual ~PhaseMonitor() = default;
  // Phase `phase` has reached `done` of `total` (in the phase's own unit, e.g. seconds of
  // simulated settling) after `steps` steps of `particles` particles.
  virtual void update(const std::string& phase, double done, double total, std::size_t steps,
                      std::size_t particles) = 0;
  // Whether the user asked to stop.
  virtual bool stop_requested() const = 0;
};

}  // namespace partimix
