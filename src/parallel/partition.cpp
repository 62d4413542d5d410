// The decomposition of a model into domains (parallel/partition.hpp, docs/parallel.md "Decomposition").
#include "crumple/parallel/partition.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <type_traits>

#include "element_graph.hpp"

namespace crumple {
namespace {

static_assert(std::is_same_v<idx_t, std::int32_t>, "the element graph is built for METIS with 32-bit indices");

// The cost of one element-cycle (internal forces, stress update, element time step) in units of 10 ns, measured
// once (docs/parallel.md, "Weights") by bench/element_costs.py: the tube of decks/tube_impact (Johnson-Cook steel,
// 10 m/s into a wall, about 770 cycles) meshed with each kind and formulation, the element phase's CPU time over
// elements x cycles, median of 3 runs, Release build, 2026-12-02; the mean of two such sets an hour apart (they
// differ by up to 30 % on the shared machine, their ratios by about 15 %). Only the ratios matter to METIS.
// Shells cost an element part plus a part per layer (through-thickness point), fitted to N = 1, 3, 5, 9:
//   Ishell 24: 404, 688, 918, 1344 ns -> 316 + 116 N; Ishell 1: 396, 816 ns at N = 1, 5, the same within 10 %
//   (Ishell 2 and 3 are Ishell 1's kernel with other hourglass forces);
//   Ishell 12 (QBAT, four in-plane points): 1173, 2756 ns at N = 1, 5 -> 777 + 396 N;
//   3-node shells: 228, 825 ns at N = 1, 5 -> 79 + 149 N;
//   resultant plasticity (N = 0), Ishell 24: 556 ns, two layers.
constexpr int kShell4Element = 32, kShell4Layer = 12;          // Ishell 1, 2, 3, 24
constexpr int kShell4QbatElement = 78, kShell4QbatLayer = 40;  // Ishell 12
constexpr int kShell3Element = 8, kShell3Layer = 15;           // Ish3n 1, 2
constexpr int kResultantLayers = 2;                            // N = 0
// Bricks: Isolid 1, 2: 653, 616 ns; Isolid 24: 2226 ns (the assumed-strain stabilisation); 2 x 2 x 2 points:
// Isolid 17 (as 12): 2104 ns; Isolid 14, 18 (assumed shears): 4833, 4796 ns.
constexpr int kBrickOnePoint = 63;        // Isolid 1, 2
constexpr int kBrickPhysical = 223;       // Isolid 24
constexpr int kBrickEightPoints = 210;    // Isolid 12, 17
constexpr int kBrickAssumedShear = 481;   // Isolid 14, 18
// Springs (/PROP/TYPE4): about 50 floating-point operations and two nodes, so of the order of 20 ns; estimated from
// the arithmetic, not yet measured by bench/element_costs.py.
constexpr int kSpring = 2;
// Trusses (/PROP/TYPE2): a spring's arithmetic and a one-dimensional return, estimated as a spring's.
constexpr int kTruss = 2;
// Beams (/PROP/TYPE3): a frame, six resultants and a yield check, about three springs' arithmetic (estimated).
constexpr int kBeam = 6;
// An element a rigid body carries is not computed (docs/theory/rigid-bodies.md); it stays in the contact surfaces
// and its nodes are moved by the body, a small cost.
constexpr int kRigidElement = 1;
// METIS's random seed: fixed, so that a model and a domain count always give the same partition.
constexpr idx_t kMetisSeed = 20261201;

// The measured cost of an element that is computed: its kind and formulation, and for shells its layers.
int computed_element_weight(const Model& model, ElementKind kind, std::size_t element) {
  const ElementTable& table = model.elements[static_cast<std::size_t>(kind)];
  const Part& part = model.parts[static_cast<std::size_t>(table.part[element])];
  const ResolvedFormulation& f = model.formulations[static_cast<std::size_t>(part.property)];
  const int layers = f.n_points == 0 ? kResultantLayers : f.n_points;
  switch (kind) {
    case ElementKind::Shell4:
      return f.ishell == 12 ? kShell4QbatElement + layers * kShell4QbatLayer : kShell4Element + layers * kShell4Layer;
    case ElementKind::Shell3:
      return kShell3Element + layers * kShell3Layer;
    case ElementKind::Brick8:
      return f.isolid == 1 || f.isolid == 2 ? kBrickOnePoint
             : f.isolid == 24               ? kBrickPhysical
             : f.isolid == 14 || f.isolid == 18 ? kBrickAssumedShear
                                                : kBrickEightPoints;
    case ElementKind::Spring: return kSpring;
    case ElementKind::Truss: return kTruss;
    case ElementKind::Beam: return kBeam;
  }
  return kBrickAssumedShear;
}

// An element's weight with its running cost: its elastic weight, plus 1 / kPlasticPointDivisor of it per point
// flowing plastically, plus its contact share (partition.hpp; the ratios from the kernels' and the contact pass's
// time over 100 cycles of the benchmark tube against the domains' elastic elements, flowing points and pairs).
int running_weight(int weight, const RunningCost* cost, int kind, std::size_t e) {
  if (cost == nullptr) return weight;
  const int points = cost->plastic[static_cast<std::size_t>(kind)][e];
  return weight + (points * weight + kPlasticPointDivisor / 2) / kPlasticPointDivisor;
}
int contact_weight(const RunningCost* cost, int kind, std::size_t e) {
  if (cost == nullptr || cost->contact[static_cast<std::size_t>(kind)].empty()) return 0;
  return cost->contact[static_cast<std::size_t>(kind)][e];
}

std::vector<std::int32_t> weights_of_elements(const Model& model, const parallel::Mesh& mesh,
                                              const std::vector<std::int32_t>& body_of_element, const RunningCost* cost) {
  std::vector<std::int32_t> weights(static_cast<std::size_t>(mesh.elements()));
  for (int k = 0; k < kElementKinds; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    const std::int32_t first = mesh.first_of_kind[static_cast<std::size_t>(k)];
    for (std::int32_t g = first; g < mesh.first_of_kind[static_cast<std::size_t>(k) + 1]; ++g) {
      const auto e = static_cast<std::size_t>(g - first);
      weights[static_cast<std::size_t>(g)] = body_of_element[static_cast<std::size_t>(g)] >= 0
                                                 ? kRigidElement
                                                 : running_weight(computed_element_weight(model, kind, e), cost, k, e);
    }
  }
  return weights;
}

// The rank counts a model admits: one per element at most, and the elements of a rigid body count once.
void check_domain_count(const parallel::Mesh& mesh, std::int32_t vertices, int domains) {
  const std::int32_t elements = mesh.elements();
  if (domains < 1) throw std::runtime_error(fmt::format("{} ranks: a run needs at least one", domains));
  if (elements == 0 && domains == 1) return;
  if (elements == 0)
    throw std::runtime_error(
        fmt::format("{} ranks for a model of 0 elements: at most 1 rank (a model without elements runs on one)", domains));
  if (domains > elements)
    throw std::runtime_error(
        fmt::format("{} ranks for a model of {} elements: at most {} ranks", domains, elements, elements));
  if (domains > vertices)
    throw std::runtime_error(fmt::format("{} ranks for a model of {} elements: at most {} ranks, since the elements "
                                         "of each rigid body stay in one domain",
                                         domains, elements, vertices));
}

const char* metis_status_text(int status) {
  return status == METIS_ERROR_INPUT ? "erroneous input" : status == METIS_ERROR_MEMORY ? "out of memory" : "error";
}

// METIS k-way on the graph, reproducible: a fixed seed, contiguous domains when the graph is connected (METIS
// refuses the option otherwise), C numbering. The load tolerance is 1 % (UFACTOR 10) instead of METIS's 3 %: the
// slowest rank sets the pace, and on the 2-million-shell tube the tighter balance costs no halo (docs/parallel.md,
// "Projection"). Returns each vertex's domain.
std::vector<idx_t> run_metis(parallel::ElementGraph& graph, int domains) {
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = kMetisSeed;
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_CONTIG] = parallel::connected(graph) ? 1 : 0;
  options[METIS_OPTION_UFACTOR] = 10;
  idx_t vertices = graph.vertices(), constraints = graph.constraints, parts = domains, cut = 0;
  std::vector<idx_t> part(static_cast<std::size_t>(vertices), 0);
  // METIS 5.1 keeps state of its random generator and allocator in globals: two threads partitioning at once (the
  // domains of the tests, ThreadExchange) got different partitions of the same graph. One call at a time.
  static std::mutex metis;
  const std::lock_guard<std::mutex> one_at_a_time(metis);
  const int status = METIS_PartGraphKway(&vertices, &constraints, graph.offsets.data(), graph.adjacency.data(),
                                         graph.vertex_weight.data(), nullptr, graph.edge_weight.data(), &parts,
                                         nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK)
    throw std::runtime_error(fmt::format("METIS could not cut the element graph ({} vertices) into {} domains: {}",
                                         vertices, domains, metis_status_text(status)));
  return part;
}

// METIS may leave a domain empty on a tiny graph; every rank must hold elements. Each empty domain takes the last
// vertex of the domain with the most vertices (the first such domain): deterministic, and rare.
void fill_empty_domains(std::vector<idx_t>& part, int domains) {
  std::vector<std::int64_t> count(static_cast<std::size_t>(domains), 0);
  for (const idx_t d : part) ++count[static_cast<std::size_t>(d)];
  for (int d = 0; d < domains; ++d) {
    if (count[static_cast<std::size_t>(d)] > 0) continue;
    const auto donor = static_cast<idx_t>(std::max_element(count.begin(), count.end()) - count.begin());
    const auto last = std::find(part.rbegin(), part.rend(), donor);
    *last = d;
    --count[static_cast<std::size_t>(donor)], ++count[static_cast<std::size_t>(d)];
  }
}

// Element-graph edges between domains: each pair of elements sharing a node counted once.
long long count_edge_cut(const parallel::Mesh& mesh, const std::vector<std::int32_t>& domain) {
  long long cut = 0;
  std::vector<std::int32_t> seen(static_cast<std::size_t>(mesh.elements()), -1);
  for (std::int32_t g = 0; g < mesh.elements(); ++g)
    parallel::for_each_neighbour(mesh, g, seen, [&](std::int32_t h) {
      if (h > g && domain[static_cast<std::size_t>(h)] != domain[static_cast<std::size_t>(g)]) ++cut;
    });
  return cut;
}

// Shared nodes (used by elements of two or more domains) and each domain's neighbours (the domains it shares a
// node with).
void count_shared_nodes(const parallel::Mesh& mesh, const std::vector<std::int32_t>& domain, Partition& p) {
  std::vector<std::vector<std::int32_t>> neighbours(static_cast<std::size_t>(p.domains));
  std::vector<std::int32_t> here;
  for (std::int32_t node = 0; node < mesh.nodes(); ++node) {
    here.clear();
    for (std::int32_t j = mesh.node_start[node]; j < mesh.node_start[node + 1]; ++j) {
      const std::int32_t d = domain[static_cast<std::size_t>(mesh.node_elements[j])];
      if (std::find(here.begin(), here.end(), d) == here.end()) here.push_back(d);
    }
    if (here.size() < 2) continue;
    ++p.shared_nodes;
    for (const std::int32_t a : here)
      for (const std::int32_t b : here)
        if (a != b) neighbours[static_cast<std::size_t>(a)].push_back(b);
  }
  p.neighbours.assign(static_cast<std::size_t>(p.domains), 0);
  for (std::size_t d = 0; d < neighbours.size(); ++d) {
    std::sort(neighbours[d].begin(), neighbours[d].end());
    p.neighbours[d] = static_cast<int>(std::unique(neighbours[d].begin(), neighbours[d].end()) - neighbours[d].begin());
  }
}

void measure_quality(const parallel::Mesh& mesh, const std::vector<std::int32_t>& domain,
                     const std::vector<std::int32_t>& weights, Partition& p) {
  p.weight.assign(static_cast<std::size_t>(p.domains), 0);
  for (std::size_t g = 0; g < domain.size(); ++g) p.weight[static_cast<std::size_t>(domain[g])] += weights[g];
  long long total = 0, largest = 0;
  for (const long long w : p.weight) total += w, largest = std::max(largest, w);
  p.imbalance = total > 0 ? static_cast<double>(largest) * p.domains / static_cast<double>(total) : 1.0;
  p.edge_cut = count_edge_cut(mesh, domain);
  count_shared_nodes(mesh, domain, p);
}

// Each element's domain, in the one numbering: METIS on the element graph, a rigid body's elements as one vertex.
std::vector<std::int32_t> domains_of_elements(const parallel::Mesh& mesh, const std::vector<std::int32_t>& body,
                                              const std::vector<std::int32_t>& weights, int domains,
                                              const std::vector<std::int32_t>* contact = nullptr) {
  check_domain_count(mesh, mesh.elements(), domains);  // before the graph: no graph for a hopeless count
  if (domains == 1) return std::vector<std::int32_t>(static_cast<std::size_t>(mesh.elements()), 0);
  parallel::ElementGraph graph = parallel::build_element_graph(mesh, body, weights, contact);
  check_domain_count(mesh, graph.vertices(), domains);
  std::vector<idx_t> part = run_metis(graph, domains);
  fill_empty_domains(part, domains);
  std::vector<std::int32_t> domain(static_cast<std::size_t>(mesh.elements()));
  for (std::size_t g = 0; g < domain.size(); ++g) domain[g] = part[static_cast<std::size_t>(graph.vertex_of_element[g])];
  return domain;
}

bool active_at_start(const Model& model, std::int32_t body) {
  const auto listed = [body](const std::vector<std::int32_t>& bodies) {
    return std::find(bodies.begin(), bodies.end(), body) != bodies.end();
  };
  return listed(model.run.bodies_on) || !listed(model.run.bodies_off);
}

bool in_body(const Model& model, const RigidBody& rb, std::int32_t node) {
  if (node == rb.main_node) return true;
  if (rb.node_group < 0) return false;
  const std::vector<std::int32_t>& nodes = model.node_groups[static_cast<std::size_t>(rb.node_group)].nodes;
  return std::binary_search(nodes.begin(), nodes.end(), node);  // sorted by the model build
}

// True when every node of the element belongs to one rigid body active at the start of the run: the rule of
// rigid_owner_of_nodes for one element, without a pass over every node (bodies that share nodes aside).
bool carried_by_rigid_body(const Model& model, ElementKind kind, std::size_t element) {
  const std::int32_t* nodes = model.elements[static_cast<std::size_t>(kind)].nodes_of(element);
  for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b) {
    if (!active_at_start(model, static_cast<std::int32_t>(b))) continue;
    const RigidBody& rb = model.rigid_bodies[b];
    if (std::all_of(nodes, nodes + nodes_per_element(kind), [&](std::int32_t n) { return in_body(model, rb, n); }))
      return true;
  }
  return false;
}

}  // namespace

int element_weight(const Model& model, ElementKind kind, std::size_t element) {
  return carried_by_rigid_body(model, kind, element) ? kRigidElement : computed_element_weight(model, kind, element);
}
int element_weight(const Model& model, ElementKind kind, std::size_t element, const RunningCost& cost) {
  if (carried_by_rigid_body(model, kind, element)) return kRigidElement;
  return running_weight(computed_element_weight(model, kind, element), &cost, static_cast<int>(kind), element);
}
int element_contact_weight(ElementKind kind, std::size_t element, const RunningCost& cost) {
  return contact_weight(&cost, static_cast<int>(kind), element);
}

Partition partition_model(const Model& model, int domains, const RunningCost* cost) {
  const parallel::Mesh mesh = parallel::build_mesh(model);
  const std::vector<std::int32_t> body =
      parallel::rigid_body_of_elements(mesh, parallel::rigid_owner_of_nodes(model));
  const std::vector<std::int32_t> weights = weights_of_elements(model, mesh, body, cost);
  // The contact cost as a second constraint, when there is any (METIS needs each constraint's total above zero).
  std::vector<std::int32_t> contact;
  if (cost != nullptr) {
    for (int k = 0; k < kElementKinds; ++k)
      for (std::size_t e = 0; e < model.elements[static_cast<std::size_t>(k)].size(); ++e)
        contact.push_back(contact_weight(cost, k, e));
    if (std::all_of(contact.begin(), contact.end(), [](std::int32_t w) { return w == 0; })) contact.clear();
  }
  const std::vector<std::int32_t> domain =
      domains_of_elements(mesh, body, weights, domains, contact.empty() ? nullptr : &contact);
  Partition p;
  p.domains = domains;
  for (std::size_t k = 0; k < static_cast<std::size_t>(kElementKinds); ++k)
    p.domain_of_element[k].assign(domain.begin() + mesh.first_of_kind[k], domain.begin() + mesh.first_of_kind[k + 1]);
  measure_quality(mesh, domain, weights, p);
  return p;
}

std::vector<std::string> describe(const Partition& p) {
  std::vector<std::string> lines{fmt::format("DOMAINS {}  EDGE CUT {}  SHARED NODES {}  IMBALANCE {:.3f}", p.domains,
                                             p.edge_cut, p.shared_nodes, p.imbalance)};
  if (p.weight.empty()) return lines;
  const auto [lightest, heaviest] = std::minmax_element(p.weight.begin(), p.weight.end());
  const auto [fewest, most] = std::minmax_element(p.neighbours.begin(), p.neighbours.end());
  long long neighbour_sum = 0;
  for (const int n : p.neighbours) neighbour_sum += n;
  lines.push_back(fmt::format("WEIGHT PER DOMAIN  MIN {}  MAX {}", *lightest, *heaviest));
  lines.push_back(fmt::format("NEIGHBOURS PER DOMAIN  MIN {}  MEAN {:.2f}  MAX {}", *fewest,
                              static_cast<double>(neighbour_sum) / p.domains, *most));
  return lines;
}

}  // namespace crumple
