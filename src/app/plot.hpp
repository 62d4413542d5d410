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

// `crumple compare A.h5 B.h5 [...] [-o DIR] [--nodes ID...]`: runs of one model side by side, a table and
// overlaid histories (the same script; README, "Trading speed for accuracy").
struct CompareOptions {
  std::vector<std::filesystem::path> results;  // two or more NAME.h5
  std::filesystem::path output_directory;      // empty: beside the first
  std::vector<long long> nodes;                // --nodes: deck ids whose final displacement the table compares
};
int compare_results(const CompareOptions& options);

}  // namespace crumple::app
