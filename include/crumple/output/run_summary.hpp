#pragma once
// NAME.summary.json: the contract for batch regression (README, "Run summary"); the summary itself is
// solver/run_summary.hpp.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "crumple/solver/run_summary.hpp"

namespace crumple {

std::string to_json(const RunSummary& summary);
// The files' sizes and CRC-32s; throws std::runtime_error naming a file that cannot be read.
std::vector<DeckFile> describe_deck_files(const std::vector<std::string>& paths);
// Now, UTC, ISO 8601 to the second.
std::string utc_now_iso8601();
void write_summary(const RunSummary& summary, const std::filesystem::path& file);
const char* status_name(RunStatus status);

}  // namespace crumple
