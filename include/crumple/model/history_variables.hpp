#pragma once
// The variables of the /TH cards Crumple accepts: the reference manual's names for the quantities Crumple computes,
// their groups (DEF, STRESS...), their dimensions, and which of them NAME.h5 records (docs/output-format.md,
// "/history/th"). One table for the reader (what it accepts and what it warns about) and the writer (what each
// column of a history dataset is).
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "crumple/core/units.hpp"
#include "crumple/model/output_requests.hpp"

namespace crumple {
struct Model;
}

namespace crumple {

struct HistoryVariable {
  std::string_view name;  // upper case, as in the manual: "DX", "|FNX|"
  std::string_view unit;  // dimension in the deck's working units, written as docs/ do: "L", "L/T", "F", "E", "-"
  Dimension dimension;    // the same as powers of M, L and T (for the SI factor)
  bool written;           // NAME.h5 records it
};

struct HistoryGroup {
  std::string_view name;                      // "DEF"
  std::span<const std::string_view> members;  // variable names, in the manual's order
};

struct HistoryKind {
  std::string_view name;  // the object word of the keyword and the prefix of the dataset: "NODE", "SHEL"...
  std::span<const HistoryVariable> variables;
  std::span<const HistoryGroup> groups;
};

const HistoryKind& history_kind(HistoryObject object);

// The variables a request names, its groups expanded, each variable once, in the order of the request; the
// names that are neither a variable nor a group of the kind go to `unknown`.
struct HistorySelection {
  std::vector<const HistoryVariable*> variables;
  std::vector<std::string> unknown;
};
HistorySelection select_history_variables(HistoryObject object, const std::vector<std::string>& requested);

// The /TH/INTER variables that sum over the interface's contact pairs (docs/output-format.md, "INTER"): the
// contact pass adds them up only for the interfaces a request asks them of.
inline constexpr std::string_view kInterfacePairSums[] = {"|FNX|", "|FNY|", "|FNZ|", "||FN||",
                                                          "|FX|",  "|FY|",  "|FZ|",  "||F||"};

// The objects (dense indices, sorted, each once) of the `object` kind for which some /TH request of the model asks
// one of `variables` (its groups expanded): what the cycle must keep for those requests and for nothing else.
std::vector<std::int32_t> objects_with_history(const Model& model, HistoryObject object,
                                               std::span<const std::string_view> variables);

// Factor that turns a value of dimension `d` in the working units `work_si` (SI size of one unit of mass, length
// and time) into SI units.
double si_factor(const Dimension& d, const double (&work_si)[3]);

}  // namespace crumple
