#pragma once
// Ctrl-C (SIGINT) asks a run to end cleanly: the Runner polls the flag once per step, writes
// the current frame and stops.
namespace partimix::app {

void install_interrupt_handler();
bool interrupt_requested();

}  // namespace partimix::app
