#pragma once
// The /TH requests as NAME.h5 records them (docs/output-format.md, "/history/th"): one dataset per request, one
// column per object and written variable, labelled; and the values of a row, computed from the model and the solver
// state at a history output time, outside the cycle's loops.
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "crumple/model/cut_sections.hpp"
#include "crumple/model/model.hpp"
#include "crumple/solver/run_summary.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple {

// One column of a history dataset.
struct HistoryColumn {
  std::int64_t object_id = 0;  // user id of the object
  std::string object_title;    // the object's title, or for nodes and elements the name the card gives it
  std::string variable;        // the manual's name: "DX"
  std::string unit;            // dimension in the deck's working units: "L", "L/T", "F", "E", "-"
  double si_scale = 1.0;       // value times si_scale: the value in SI units
  std::string label;           // "<dataset>/<object id>/<variable>", unique in the file
};

// One /TH request: /history/th/<name>, rows x columns, the columns object by object, the variables of each in the
// order of the request (groups expanded).
struct HistoryDataset {
  std::string name;     // "<KIND>_<thgroup id>", e.g. "NODE_2" (a second card of the same kind and id: "NODE_2_2")
  std::string kind;     // "NODE", "PART", "SUBS", "SHEL", "SH3N", "BRIC", "INTER", "RWALL", "RBODY", "SECTIO", "ACCEL"
  std::string keyword;  // the card's keyword line: "/TH/NODE/2"
  std::int64_t id = 0;  // thgroup id
  std::string title;
  std::vector<HistoryColumn> columns;
};

class HistoryChannels {
 public:
  // The datasets of the model's requests: every request with at least one object and one written variable.
  explicit HistoryChannels(const Model& model);

  const std::vector<HistoryDataset>& datasets() const { return datasets_; }

  // The values of one row of every dataset (values[d] gets datasets()[d].columns.size() values) for `state` at a
  // history output time; `change` is the cycle's velocity update (accelerations and reactions are NaN without it).
  void evaluate(const SolverState& state, const VelocityChange& change,
                std::vector<std::vector<double>>& values) const;
  // Every part's mass and energies in `state`, /TH/PART's IE, KE + RKE, HE and MASS (the run's part table).
  std::vector<PartResult> part_results(const SolverState& state) const;

 private:
  struct Request {
    HistoryObject object;
    std::vector<std::int32_t> objects;  // dense indices
    std::vector<int> getters;           // per variable: the kind's evaluator
    std::vector<std::int32_t> skews;    // nodes: per object, the skew its vectors are written in (-1: global)
  };
  struct PartSums;

  void add_request(const TimeHistoryRequest& th);
  void split_nodes_by_part();
  void gather_subsets();
  PartSums part_sums(const SolverState& state) const;
  void evaluate(const Request& r, const SolverState& state, const VelocityChange& change, const PartSums* parts,
                std::vector<double>& row) const;

  const Model& model_;
  std::vector<HistoryDataset> datasets_;
  std::vector<Request> requests_;  // parallel to datasets_
  bool needs_parts_ = false;
  // Each node's share of each part (docs/output-format.md, "Parts"): node k has the shares
  // node_share_[node_share_offset_[k] .. node_share_offset_[k + 1]).
  std::vector<std::size_t> node_share_offset_;
  std::vector<std::pair<std::int32_t, double>> node_share_;  // part, share
  std::vector<std::vector<std::int32_t>> subset_parts_;      // per subset: its parts and its subsets' parts, once each
  std::array<std::vector<std::int32_t>, kElementKinds> element_group_;  // per element of each kind: its group
  std::vector<std::vector<SectionTerm>> section_terms_;  // per /SECT (written ones only): what its values sum
};

}  // namespace crumple
