#pragma once
/// \file interrupt_flag.hpp
/// Ctrl-C for long runs: SIGINT/SIGTERM only set a flag (the one piece of global state
/// the apps have); the run loop polls it between steps, finishes the current step and
/// frame, closes its files and exits with code 130. A second signal ends the process
/// at once (the handler is installed with SA_RESETHAND).
namespace fsi::app {

/// Installs the handler for SIGINT and SIGTERM.
void install_interrupt_handlers();

/// True once SIGINT or SIGTERM arrived.
bool interrupt_requested();

/// The exit code of a run stopped by a signal (128 + SIGINT).
inline constexpr int kExitInterrupted = 130;

}  // namespace fsi::app
