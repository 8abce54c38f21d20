#pragma once
// Ctrl-C (SIGINT) and SIGTERM (a batch system ending a job, `kill`) ask partimix to end cleanly:
// the Runner polls the flag once per step, writes a checkpoint, the current sample and frame and
// run.json with status "interrupted", and stops; set-up phases poll it too
// (app/console_monitor.hpp).
namespace partimix::app {

void install_interrupt_handler();
bool interrupt_requested();

}  // namespace partimix::app
