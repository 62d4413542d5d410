// crumple: command-line entry point. Turns library errors into messages and exit codes (exit_codes.hpp);
// nothing below this file calls exit().
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>

#include "app/check.hpp"
#include "app/console.hpp"
#include "app/exit_codes.hpp"
#include "app/plot.hpp"
#include "crumple/output/build_info.hpp"
#include "app/regress.hpp"
#include "app/run.hpp"
#include "app/th.hpp"
#include "crumple/deck/reader.hpp"
#include "crumple/output/restart_file.hpp"

namespace {

int report_deck_errors(const std::vector<crumple::DeckError>& errors) {
  for (const auto& e : errors) fmt::print(stderr, "error: {}\n", e.what());
  fmt::print(stderr, "crumple: {} error{} in the deck; nothing was computed\n", errors.size(),
             errors.size() == 1 ? "" : "s");
  return crumple::app::kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace crumple;
  CLI::App cli{"Crumple - explicit finite-element crash solver for Radioss block-format decks"};
  cli.set_version_flag("--version", std::string("crumple ") + build::version() + " (" + build::commit() + ")");
  cli.require_subcommand(1);

  std::string deck_path;
  bool skip_unknown = false;
  bool quiet = false;
  app::RunOptions run_options;

  CLI::App* check = cli.add_subcommand("check", "Read and validate a deck and print a model summary");
  check->add_option("DECK", deck_path, "Starter deck (NAME_0000.rad); NAME_0001.rad beside it is read too")
      ->required();
  const char* const skip_help =
      "Skip keywords and options Crumple lacks (unknown or not supported) with a warning instead of failing";
  check->add_flag("--skip-unknown", skip_unknown, skip_help);
  int ranks = 0;
  check->add_option("--ranks", ranks,
                    "Also partition the model for N ranks (METIS) and print the partition's quality")
      ->check(CLI::PositiveNumber);

  CLI::App* run = cli.add_subcommand("run", "Run a deck: writes NAME.h5, NAME.out and NAME.summary.json");
  run->add_option("DECK", deck_path, "Starter deck (NAME_0000.rad) with its engine deck beside it")->required();
  run->add_option("-o,--output", run_options.output_directory, "Output directory (default: current directory)");
  run->add_flag("--skip-unknown", skip_unknown, skip_help);
  std::string accuracy = "standard";
  run->add_option("--accuracy", accuracy,
                  "Speed-accuracy preset: draft (nodal mass scaling, /DT/NODA/CST 0.67, to 0.6 times the step the "
                  "1 % smallest elements start with), standard (the deck as written, the default) or fine (step scale 0.6, no "
                  "added mass, 5 shell points, contact steps that anticipate a node's entry into the gap); every "
                  "change is listed (docs/performance.md)")
      ->check(CLI::IsMember({"draft", "standard", "fine"}));
  run->add_option("--restart", run_options.restart,
                  "Resume from a restart file (NAME.rst, written with /RFILE or when a run is stopped); the "
                  "folder's NAME.h5 and NAME.out are continued, not replaced");
  run->add_flag("--overwrite", run_options.overwrite,
                "With --restart: replace the folder's NAME.h5 and NAME.out by the resumed run's instead of "
                "continuing them");

  app::RegressOptions regress_options;
  CLI::App* regress = cli.add_subcommand(
      "regress", "Run every deck folder holding a ref.extract under DIR... and compare with the reference");
  regress->add_option("DIR", regress_options.folders, "Folders searched for deck folders (ref.extract + NAME_0000.rad)")
      ->required()
      ->check(CLI::ExistingDirectory);
  regress->add_option("-j,--jobs", regress_options.jobs, "Runs at once (default: the core count)")
      ->check(CLI::PositiveNumber);
  regress->add_option("--timeout", regress_options.timeout_seconds, "Time limit of each run in seconds (default 600)")
      ->check(CLI::PositiveNumber);
  regress->add_option("--junit", regress_options.junit, "Write a JUnit XML report to FILE");
  regress->add_option("--work", regress_options.work,
                      "Folder for the runs' output directories (default: a temporary folder, removed when all pass)");
  regress->add_flag("--skip-unknown", regress_options.skip_unknown, "Pass --skip-unknown to each run");

  app::PlotOptions plot_options;
  CLI::App* plot = cli.add_subcommand("plot", "Draw PNGs of a results file's histories (energy balance, contact and "
                                              "wall forces, sections, selected /TH columns) with matplotlib");
  plot->add_option("RESULTS", plot_options.results, "Results file NAME.h5")->required();
  plot->add_option("-o,--output", plot_options.output_directory, "Folder for the PNGs (default: beside NAME.h5)");
  plot->add_option("--select", plot_options.select, "Also plot the /history/th columns whose label contains PATTERN")
      ->expected(1, -1);
  app::CompareOptions compare_options;
  CLI::App* compare = cli.add_subcommand(
      "compare", "Runs of one model side by side: a table of cycles, wall time, internal energy, wall forces and "
                 "node displacements against the first run, and their histories overlaid (PNGs)");
  compare->add_option("RESULTS", compare_options.results, "Two or more results files NAME.h5")->required()->expected(2, -1);
  compare->add_option("-o,--output", compare_options.output_directory, "Folder for the PNGs (default: beside the first)");
  compare->add_option("--nodes", compare_options.nodes, "Also compare these nodes' final displacements (deck ids)")
      ->expected(1, -1);
  run->add_flag("-q,--quiet", quiet,
                "No progress on the console (by default a line updated once a second on a terminal, otherwise "
                "printed every 5 s)");

  app::ThOptions th_options;
  CLI::App* th = cli.add_subcommand("th", "List the time histories of NAME.h5, or export them as CSV");
  th->add_option("FILE", th_options.file, "Results file NAME.h5 written by crumple run")->required();
  th->add_flag("--csv", th_options.csv, "Write the histories as CSV: time first, one column per channel");
  th->add_option("--select", th_options.select,
                 "Only the columns whose label matches one of these glob patterns, e.g. 'NODE_2/*/DX' 'internal'");
  th->add_option("-o,--output", th_options.output, "CSV file to write (default: standard output)");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? app::kExitNormal : app::kExitBadInput;
  }

  try {
    if (check->parsed()) {
      ReadOptions options;
      options.skip_unknown = skip_unknown;
      const Deck deck = read_deck(deck_path, options);
      Partition partition;
      if (ranks > 0) {
        try {
          partition = partition_model(deck.model, ranks);
        } catch (const std::runtime_error& e) {  // a rank count the model does not admit
          fmt::print(stderr, "crumple: {}\n", e.what());
          return app::kExitBadInput;
        }
      }
      app::print_check_report(deck, std::cout);
      if (ranks > 0) app::print_partition_report(partition, std::cout);
      return app::kExitNormal;
    }
    if (regress->parsed()) return app::regress(regress_options, std::cout, std::cerr);
    if (plot->parsed()) return app::plot_results(plot_options);
    if (compare->parsed()) return app::compare_results(compare_options);
    if (th->parsed()) return app::run_th(th_options, std::cout, std::cerr);
    run_options.deck = deck_path;
    run_options.skip_unknown = skip_unknown;
    run_options.progress = app::stdout_progress(quiet);
    run_options.accuracy = app::accuracy_preset(accuracy);
    return app::run_deck(run_options, std::cout, std::cerr);
  } catch (const DeckErrors& e) {
    return report_deck_errors(e.errors());
  } catch (const DeckError& e) {
    return report_deck_errors({e});
  } catch (const RestartError& e) {
    fmt::print(stderr, "crumple: {}\n", e.what());
    return app::kExitBadInput;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "crumple: out of memory\n");
    return app::kExitRunFailed;
  } catch (const std::exception& e) {
    fmt::print(stderr, "crumple: internal error: {}\n", e.what());
    return app::kExitInternal;
  }
}
