#pragma once
// The command-line contract (README, "Exit codes").
namespace crumple::app {
inline constexpr int kExitNormal = 0;     // the command did what was asked
inline constexpr int kExitRunFailed = 1;  // a run stopped abnormally (instability, /STOP limit, solver error)
inline constexpr int kExitBadInput = 2;   // the deck or the command line is invalid; nothing was computed
inline constexpr int kExitInternal = 3;   // a bug in Crumple: please report it with the deck
inline constexpr int kExitStopped = 4;    // SIGINT (Ctrl-C) or SIGTERM stopped the run; its files end where it stopped
}  // namespace crumple::app
