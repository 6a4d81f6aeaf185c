// SIGINT and SIGTERM as a request to stop: while a StopSignals lives, the first of either
// signal sets a flag the render loop polls between passes (a second one ends the process as
// the default action would).
#pragma once

namespace tr {

class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  bool raised() const;
};

}  // namespace tr
