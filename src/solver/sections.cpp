// /TH/SECTIO in the solver (include/crumple/solver/sections.hpp, docs/output-format.md "SECTIO").
#include "crumple/solver/sections.hpp"

#include <algorithm>
#include <string_view>

#include "crumple/model/cut_sections.hpp"
#include "crumple/model/history_variables.hpp"
#include "crumple/state/element_status.hpp"

namespace crumple {
namespace {

constexpr std::string_view kWork[] = {"WORK"};

ElementRecords& records_of(SolverState& s, ElementKind kind) { return element_state(s, kind).records; }

std::vector<double>& section_work_of(SolverState& s, ElementKind kind) { return element_state(s, kind).section_work; }

// Per kind, per element: 1 when one of `sections` reads it.
std::array<std::vector<std::uint8_t>, kElementKinds> read_elements(const Model& m,
                                                                   const std::vector<std::int32_t>& sections) {
  std::array<std::vector<std::uint8_t>, kElementKinds> read;
  for (int k = 0; k < kElementKinds; ++k)
    read[static_cast<std::size_t>(k)].assign(m.elements[static_cast<std::size_t>(k)].size(), 0);
  for (std::int32_t section : sections) {
    const auto elements = section_elements(m, m.sections[static_cast<std::size_t>(section)]);
    for (int k = 0; k < kElementKinds; ++k)
      for (std::int32_t e : elements[static_cast<std::size_t>(k)])
        read[static_cast<std::size_t>(k)][static_cast<std::size_t>(e)] = 1;
  }
  return read;
}

// One domain: the groups that hold a read element record, and the records cover the elements up to the last of
// them.
void record_groups(const Model& m, SolverState& s, const std::array<std::vector<std::uint8_t>, kElementKinds>& read) {
  std::array<std::vector<std::uint8_t>, kElementKinds> only;
  std::array<std::size_t, kElementKinds> end{};
  for (const ElementGroup& g : m.element_groups) {
    const auto k = static_cast<std::size_t>(g.kind);
    const auto& r = read[k];
    if (!std::any_of(r.begin() + g.begin, r.begin() + g.end, [](std::uint8_t x) { return x != 0; })) continue;
    if (only[k].empty()) only[k].assign(r.size(), 0);
    only[k][static_cast<std::size_t>(g.begin)] = 1;
    end[k] = std::max(end[k], static_cast<std::size_t>(g.end));
  }
  for (int k = 0; k < kElementKinds; ++k) {
    if (end[static_cast<std::size_t>(k)] == 0) continue;
    const auto kind = static_cast<ElementKind>(k);
    ElementRecords& records = records_of(s, kind);
    records.start(end[static_cast<std::size_t>(k)], nodes_per_element(kind), describe(kind).values_per_node);
    records.only = std::move(only[static_cast<std::size_t>(k)]);
  }
}

// The sections some /TH/SECTIO request writes a value of.
std::vector<std::int32_t> written_sections(const Model& m) {
  std::vector<std::string_view> names;
  for (const HistoryVariable& v : history_kind(HistoryObject::Section).variables)
    if (v.written) names.push_back(v.name);
  return objects_with_history(m, HistoryObject::Section, names);
}

}  // namespace

void setup_sections(const Model& m, SolverState& s) { bind_sections(m, s, false); }

void bind_sections(const Model& m, SolverState& s, bool keep_work) {
  HistoryIntegrals& h = s.histories;
  const std::vector<std::int32_t> written = written_sections(m);
  if (written.empty()) return;
  const auto read = read_elements(m, written);
  if (!s.domain.several()) {
    record_groups(m, s, read);
  } else {
    for (int k = 0; k < kElementKinds; ++k) {
      auto& owner = h.section_record_owner[static_cast<std::size_t>(k)];
      const auto& r = read[static_cast<std::size_t>(k)];
      owner.assign(r.size(), -1);
      for (std::size_t e = 0; e < r.size(); ++e)
        if (r[e] != 0) owner[e] = s.domain.owner[static_cast<std::size_t>(k)][e];
      // This domain's groups that hold a read element record (the domain records only the groups others need).
      ElementRecords& records = records_of(s, static_cast<ElementKind>(k));
      for (const ElementGroup& g : m.element_groups)
        if (static_cast<int>(g.kind) == k && std::any_of(r.begin() + g.begin, r.begin() + g.end, [](std::uint8_t x) { return x != 0; }))
          records.only[static_cast<std::size_t>(g.begin)] = 1;
    }
  }
  const auto work = read_elements(m, objects_with_history(m, HistoryObject::Section, kWork));
  for (int k = 0; k < kElementKinds; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    auto& elements = h.section_work_elements[static_cast<std::size_t>(k)];
    const auto& w = work[static_cast<std::size_t>(k)];
    elements.clear();
    for (std::size_t e = 0; e < w.size(); ++e)
      if (w[e] != 0 && (!s.domain.several() || s.domain.mine(kind, e)))
        elements.push_back(static_cast<std::int32_t>(e));
    if (!keep_work && std::any_of(w.begin(), w.end(), [](std::uint8_t x) { return x != 0; }))
      section_work_of(s, kind).assign(w.size() * static_cast<std::size_t>(nodes_per_element(kind)), 0.0);
  }
}

void add_section_work(const Model& m, SolverState& s, const std::array<std::vector<double>, 6>& before, double dt) {
  const HistoryIntegrals& h = s.histories;
  const NodalState& n = s.nodes;
  const std::vector<double>* now[6] = {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz};
  for (int k = 0; k < kElementKinds; ++k) {
    const std::vector<std::int32_t>& elements = h.section_work_elements[static_cast<std::size_t>(k)];
    if (elements.empty()) continue;
    const auto kind = static_cast<ElementKind>(k);
    const ElementTable& table = m.elements[static_cast<std::size_t>(k)];
    ElementRecords& records = records_of(s, kind);
    std::vector<double>& work = section_work_of(s, kind);
    const int count = nodes_per_element(kind), values = records.values_per_node;
    for (std::int32_t e : elements) {
      const auto ue = static_cast<std::size_t>(e);
      const std::int32_t* nodes = table.nodes_of(ue);
      for (int a = 0; a < count; ++a) {
        const auto node = static_cast<std::size_t>(nodes[a]);
        const double* load = records.load_at(ue, a);
        double power = 0.0;  // f . v_mid (+ m . w_mid)
        for (int c = 0; c < values; ++c)
          power += load[c] * 0.5 * (before[static_cast<std::size_t>(c)][node] + (*now[c])[node]);
        work[ue * static_cast<std::size_t>(count) + static_cast<std::size_t>(a)] += dt * power;
      }
    }
  }
}

void share_section_records(SolverState& s, Exchange* exchange) {
  if (exchange == nullptr) return;
  for (int k = 0; k < kElementKinds; ++k) {
    const std::vector<std::int32_t>& owner = s.histories.section_record_owner[static_cast<std::size_t>(k)];
    if (owner.empty()) continue;
    ElementRecords& records = records_of(s, static_cast<ElementKind>(k));
    exchange->share(records.load, records.nodes_per_element * records.values_per_node, owner);
  }
}

}  // namespace crumple
