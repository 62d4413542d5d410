#pragma once
// `crumple plot NAME.h5 [-o DIR] [--select PATTERN...]`: PNGs of the histories with matplotlib (the script
// src/app/plot/crumple_plot.py, embedded in the binary, run by the system Python; docs/output-format.md, "Plots").
#include <filesystem>
#include <string>
#include <vector>

namespace crumple::app {

struct PlotOptions {
  std::filesystem::path results;        // NAME.h5
  std::filesystem::path output_directory;  // empty: beside NAME.h5
  std::vector<std::string> select;      // --select: label patterns of /history/th columns
};

// The Python that runs the plots: $CRUMPLE_PYTHON, else /usr/bin/python3 (Debian's, with matplotlib and h5py),
// else python3 on the PATH.
std::string plot_python();

// Runs the plot script; returns the process exit code (0, or 2 with the script's message on stderr).
int plot_results(const PlotOptions& options);

}  // namespace crumple::app
