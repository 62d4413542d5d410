// The /TH variable tables (include/crumple/model/history_variables.hpp). Names, groups and meanings follow the
// reference manual's /TH/<kind> pages (docs/cards/loads-output-engine.md §6.1); what each written variable is in
// Crumple: docs/output-format.md, "/history/th".
#include "crumple/model/history_variables.hpp"

#include "crumple/model/model.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace crumple {
namespace {

using V = HistoryVariable;
using G = HistoryGroup;
using S = std::string_view;

// Dimensions, as docs/ write them.
constexpr Dimension kNone{0, 0, 0}, kLength{0, 1, 0}, kVelocity{0, 1, -1}, kAcceleration{0, 1, -2},
    kRate{0, 0, -1}, kAngularAcceleration{0, 0, -2}, kForce{1, 1, -2}, kMoment{1, 2, -2}, kMass{1, 0, 0},
    kMomentum{1, 1, -1}, kAngularMomentum{1, 2, -1}, kInertia{1, 2, 0}, kForcePerLength{1, 0, -2},
    kStress{1, -1, -2}, kDensity{1, -3, 0}, kArea{0, 2, 0}, kVolume{0, 3, 0}, kCurvature{0, -1, 0};

// ---- /TH/NODE
constexpr std::array<V, 27> kNode{{
    {"DX", "L", kLength, true},         {"DY", "L", kLength, true},         {"DZ", "L", kLength, true},
    {"VX", "L/T", kVelocity, true},     {"VY", "L/T", kVelocity, true},     {"VZ", "L/T", kVelocity, true},
    {"AX", "L/T^2", kAcceleration, true}, {"AY", "L/T^2", kAcceleration, true}, {"AZ", "L/T^2", kAcceleration, true},
    {"VRX", "1/T", kRate, true},        {"VRY", "1/T", kRate, true},        {"VRZ", "1/T", kRate, true},
    {"ARX", "1/T^2", kAngularAcceleration, true}, {"ARY", "1/T^2", kAngularAcceleration, true},
    {"ARZ", "1/T^2", kAngularAcceleration, true},
    {"X", "L", kLength, true},          {"Y", "L", kLength, true},          {"Z", "L", kLength, true},
    {"REACX", "F", kForce, true},       {"REACY", "F", kForce, true},       {"REACZ", "F", kForce, true},
    {"REACXX", "F L", kMoment, true},   {"REACYY", "F L", kMoment, true},   {"REACZZ", "F L", kMoment, true},
    // The integral of the angular velocity, kept by the cycle for the nodes asked (solver/node_rotations.hpp).
    {"DRX", "-", kNone, true},          {"DRY", "-", kNone, true},          {"DRZ", "-", kNone, true}}};
constexpr std::array<S, 6> kNodeDef{"DX", "DY", "DZ", "VX", "VY", "VZ"};
constexpr std::array<S, 3> kNodeD{"DX", "DY", "DZ"}, kNodeV{"VX", "VY", "VZ"}, kNodeA{"AX", "AY", "AZ"},
    kNodeVR{"VRX", "VRY", "VRZ"}, kNodeAR{"ARX", "ARY", "ARZ"}, kNodeXYZ{"X", "Y", "Z"};
constexpr std::array<G, 7> kNodeGroups{{{"DEF", kNodeDef}, {"D", kNodeD}, {"V", kNodeV}, {"A", kNodeA},
                                        {"VR", kNodeVR}, {"AR", kNodeAR}, {"XYZ", kNodeXYZ}}};

// ---- /TH/PART and /TH/SUBS
constexpr std::array<V, 23> kPart{{
    {"IE", "E", kMoment, true},           {"KE", "E", kMoment, true},          {"XMOM", "M L/T", kMomentum, true},
    {"YMOM", "M L/T", kMomentum, true},   {"ZMOM", "M L/T", kMomentum, true},  {"MASS", "M", kMass, true},
    {"HE", "E", kMoment, true},           {"XCG", "L", kLength, true},         {"YCG", "L", kLength, true},
    {"ZCG", "L", kLength, true},          {"RKE", "E", kMoment, true},
    // Angular momenta, inertia tensors and the rigid-body energies: the manual gives no reference point, sign of
    // the products of inertia nor content of RIE, KERB, RKERB (docs/output-format.md, "PART").
    {"XXMOM", "M L^2/T", kAngularMomentum, false}, {"YYMOM", "M L^2/T", kAngularMomentum, false},
    {"ZZMOM", "M L^2/T", kAngularMomentum, false}, {"IXX", "M L^2", kInertia, false},
    {"IYY", "M L^2", kInertia, false},    {"IZZ", "M L^2", kInertia, false},   {"IXY", "M L^2", kInertia, false},
    {"IYZ", "M L^2", kInertia, false},    {"IZX", "M L^2", kInertia, false},   {"RIE", "E", kMoment, false},
    {"KERB", "E", kMoment, false},        {"RKERB", "E", kMoment, false}}};
constexpr std::array<S, 7> kPartDef{"IE", "KE", "XMOM", "YMOM", "ZMOM", "MASS", "HE"};
constexpr std::array<G, 1> kPartGroups{{{"DEF", kPartDef}}};

// ---- /TH/SHEL, /TH/SH3N
constexpr std::array<V, 23> kShell{{
    {"F1", "F/L", kForcePerLength, true},  {"F2", "F/L", kForcePerLength, true},
    {"F12", "F/L", kForcePerLength, true}, {"Q1", "F/L", kForcePerLength, true},
    {"Q2", "F/L", kForcePerLength, true},  {"M1", "F", kForce, true},
    {"M2", "F", kForce, true},             {"M12", "F", kForce, true},
    // The element's internal energy is not split into membrane and bending parts.
    {"IEM", "E", kMoment, false},          {"IEB", "E", kMoment, false},
    {"OFF", "-", kNone, true},             {"THIC", "L", kLength, true},
    {"EMIN", "-", kNone, true},            {"EMAX", "-", kNone, true},
    {"EPSD", "1/T", kRate, true},
    // Strains and curvatures are not kept by the shell kernels (only their rates, within the cycle).
    {"E1", "-", kNone, false},             {"E2", "-", kNone, false},             {"E12", "-", kNone, false},
    {"SH1", "-", kNone, false},            {"SH2", "-", kNone, false},            {"K1", "1/L", kCurvature, false},
    {"K2", "1/L", kCurvature, false},      {"K12", "1/L", kCurvature, false}}};
constexpr std::array<S, 11> kShellDef{"F1", "F2", "F12", "M1", "M2", "M12", "IEM", "IEB", "OFF", "EMIN", "EMAX"};
constexpr std::array<S, 8> kShellStress{"F1", "F2", "F12", "Q1", "Q2", "M1", "M2", "M12"};
constexpr std::array<S, 8> kShellStrain{"E1", "E2", "E12", "SH1", "SH2", "K1", "K2", "K12"};
constexpr std::array<S, 2> kShellPlas{"EMIN", "EMAX"};
constexpr std::array<G, 4> kShellGroups{
    {{"DEF", kShellDef}, {"STRESS", kShellStress}, {"STRAIN", kShellStrain}, {"PLAS", kShellPlas}}};

// ---- /TH/BRIC
constexpr std::array<V, 19> kBrick{{
    {"OFF", "-", kNone, true},       {"SX", "F/L^2", kStress, true},    {"SY", "F/L^2", kStress, true},
    {"SZ", "F/L^2", kStress, true},  {"SXY", "F/L^2", kStress, true},   {"SYZ", "F/L^2", kStress, true},
    {"SXZ", "F/L^2", kStress, true}, {"IE", "E", kMoment, true},        {"DENS", "M/L^3", kDensity, true},
    // The bulk viscosity is a term of the cycle, the plastic strain rate is not kept (only the total rate).
    {"BULK", "F/L^2", kStress, false}, {"VOL", "L^3", kVolume, true},   {"PLAS", "-", kNone, true},
    {"PLSR", "1/T", kRate, false},
    // Strains are not kept by the brick kernels.
    {"EPSXX", "-", kNone, false},    {"EPSYY", "-", kNone, false},      {"EPSZZ", "-", kNone, false},
    {"EPSXY", "-", kNone, false},    {"EPSXZ", "-", kNone, false},      {"EPSYZ", "-", kNone, false}}};
// The manual's DEF ends with TEMP, which Crumple has not (no thermal analysis).
constexpr std::array<S, 10> kBrickDef{"OFF", "SX", "SY", "SZ", "SXY", "SYZ", "SXZ", "IE", "DENS", "PLAS"};
constexpr std::array<S, 6> kBrickStress{"SX", "SY", "SZ", "SXY", "SYZ", "SXZ"};
constexpr std::array<S, 6> kBrickStrain{"EPSXX", "EPSYY", "EPSZZ", "EPSXY", "EPSXZ", "EPSYZ"};
constexpr std::array<G, 3> kBrickGroups{{{"DEF", kBrickDef}, {"STRESS", kBrickStress}, {"STRAIN", kBrickStrain}}};

// ---- /TH/INTER
constexpr std::array<V, 20> kInterface{{
    {"FNX", "F", kForce, true},      {"FNY", "F", kForce, true},      {"FNZ", "F", kForce, true},
    {"FTX", "F", kForce, true},      {"FTY", "F", kForce, true},      {"FTZ", "F", kForce, true},
    // Sums over the contact pairs (the pass adds them up for the interfaces asked: kInterfacePairSums).
    {"|FNX|", "F", kForce, true},    {"|FNY|", "F", kForce, true},    {"|FNZ|", "F", kForce, true},
    {"||FN||", "F", kForce, true},   {"|FX|", "F", kForce, true},     {"|FY|", "F", kForce, true},
    {"|FZ|", "F", kForce, true},     {"||F||", "F", kForce, true},
    // The moments: the manual does not say about which point, nor where on the pair the force acts.
    {"MX", "F L", kMoment, false},   {"MY", "F L", kMoment, false},   {"MZ", "F L", kMoment, false},
    {"CE_ELAST", "E", kMoment, true}, {"CE_FRIC", "E", kMoment, true}, {"CE_DAMP", "E", kMoment, true}}};
constexpr std::array<S, 6> kForcesDef{"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ"};
constexpr std::array<S, 3> kForcesFN{"FNX", "FNY", "FNZ"}, kForcesFT{"FTX", "FTY", "FTZ"};
constexpr std::array<S, 4> kInterfaceAbsFN{"|FNX|", "|FNY|", "|FNZ|", "||FN||"},
    kInterfaceAbsF{"|FX|", "|FY|", "|FZ|", "||F||"};
constexpr std::array<G, 5> kInterfaceGroups{
    {{"DEF", kForcesDef}, {"FN", kForcesFN}, {"FT", kForcesFT}, {"|FN|", kInterfaceAbsFN}, {"|F|", kInterfaceAbsF}}};

// ---- /TH/RWALL
constexpr std::array<V, 6> kWall{{{"FNX", "F", kForce, true}, {"FNY", "F", kForce, true}, {"FNZ", "F", kForce, true},
                                  {"FTX", "F", kForce, true}, {"FTY", "F", kForce, true}, {"FTZ", "F", kForce, true}}};
constexpr std::array<G, 1> kWallGroups{{{"DEF", kForcesDef}}};

// ---- /TH/RBODY
constexpr std::array<V, 9> kBody{{{"FX", "F", kForce, true},     {"FY", "F", kForce, true},     {"FZ", "F", kForce, true},
                                  {"MX", "F L", kMoment, true},  {"MY", "F L", kMoment, true},  {"MZ", "F L", kMoment, true},
                                  {"RX", "-", kNone, true},      {"RY", "-", kNone, true},      {"RZ", "-", kNone, true}}};
constexpr std::array<S, 9> kBodyDef{"FX", "FY", "FZ", "MX", "MY", "MZ", "RX", "RY", "RZ"};
constexpr std::array<S, 3> kBodyF{"FX", "FY", "FZ"}, kBodyM{"MX", "MY", "MZ"}, kBodyR{"RX", "RY", "RZ"};
constexpr std::array<G, 4> kBodyGroups{{{"DEF", kBodyDef}, {"F", kBodyF}, {"M", kBodyM}, {"R", kBodyR}}};

// ---- /TH/SECTIO: the loads the section's elements hand the nodes of its cut (docs/output-format.md, "SECTIO").
// WORKR: the manual names it without saying what it is; DFX..DMZ: the errors of a section whose motion is imposed
// from a file (ISAVE 100, 200), which Crumple does not read.
constexpr std::array<V, 26> kSection{{
    {"FNX", "F", kForce, true},    {"FNY", "F", kForce, true},    {"FNZ", "F", kForce, true},
    {"FTX", "F", kForce, true},    {"FTY", "F", kForce, true},    {"FTZ", "F", kForce, true},
    {"M1", "F L", kMoment, true},  {"M2", "F L", kMoment, true},  {"M3", "F L", kMoment, true},
    {"WORK", "E", kMoment, true},  {"WORKR", "E", kMoment, false},
    {"MX", "F L", kMoment, true},  {"MY", "F L", kMoment, true},  {"MZ", "F L", kMoment, true},
    {"F1", "F", kForce, true},     {"F2", "F", kForce, true},     {"F3", "F", kForce, true},
    {"CX", "L", kLength, true},    {"CY", "L", kLength, true},    {"CZ", "L", kLength, true},
    {"DFX", "F", kForce, false},   {"DFY", "F", kForce, false},   {"DFZ", "F", kForce, false},
    {"DMX", "F L", kMoment, false}, {"DMY", "F L", kMoment, false}, {"DMZ", "F L", kMoment, false}}};
constexpr std::array<S, 9> kSectionDef{"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "M1", "M2", "M3"},
    kSectionGlobal{"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "MX", "MY", "MZ"};
constexpr std::array<S, 6> kSectionLocal{"F1", "F2", "F3", "M1", "M2", "M3"};
constexpr std::array<S, 3> kSectionFN{"FNX", "FNY", "FNZ"}, kSectionFT{"FTX", "FTY", "FTZ"},
    kSectionM{"M1", "M2", "M3"}, kSectionCenter{"CX", "CY", "CZ"};
constexpr std::array<G, 7> kSectionGroups{{{"DEF", kSectionDef}, {"FN", kSectionFN}, {"FT", kSectionFT},
                                           {"M", kSectionM}, {"CENTER", kSectionCenter}, {"GLOBAL", kSectionGlobal},
                                           {"LOCAL", kSectionLocal}}};

// ---- /TH/ACCEL: the accelerometer's filtered acceleration and the integral of its raw acceleration. The manual's
// groups table reads "DEF W"; the reference starter lists DEF as AX AY AZ (its listing of the QA deck
// rbody_rotation: "3 VAR ... AX AY AZ"), so W is the integrals.
constexpr std::array<V, 6> kAccelerometer{{
    {"AX", "L/T^2", kAcceleration, true}, {"AY", "L/T^2", kAcceleration, true}, {"AZ", "L/T^2", kAcceleration, true},
    {"WX", "L/T", kVelocity, true},       {"WY", "L/T", kVelocity, true},       {"WZ", "L/T", kVelocity, true}}};
constexpr std::array<S, 3> kAccelerometerDef{"AX", "AY", "AZ"}, kAccelerometerW{"WX", "WY", "WZ"};
constexpr std::array<G, 2> kAccelerometerGroups{{{"DEF", kAccelerometerDef}, {"W", kAccelerometerW}}};

// ---- /TH/SPRING: the manual's variables in the spring's frame (X along its nodes); a /PROP/TYPE4 spring carries
// the axial force FX and the elongation LX only, so the others are 0. LENGTH, the current length, is in the
// reference's DEF (its starter listing of damping_springs: "15 VAR ... IE LENGTH"). F1, F2 are the pulley's.
constexpr std::array<V, 17> kSpring{{
    {"OFF", "-", kNone, true},      {"FX", "F", kForce, true},       {"FY", "F", kForce, true},
    {"FZ", "F", kForce, true},      {"MX", "F L", kMoment, true},    {"MY", "F L", kMoment, true},
    {"MZ", "F L", kMoment, true},   {"LX", "L", kLength, true},      {"LY", "L", kLength, true},
    {"LZ", "L", kLength, true},     {"RX", "-", kNone, true},        {"RY", "-", kNone, true},
    {"RZ", "-", kNone, true},       {"IE", "E", kMoment, true},      {"LENGTH", "L", kLength, true},
    {"F1", "F", kForce, false},     {"F2", "F", kForce, false}}};
constexpr std::array<S, 15> kSpringDef{"OFF", "FX", "FY", "FZ", "MX", "MY", "MZ", "LX",
                                       "LY",  "LZ", "RX", "RY", "RZ", "IE", "LENGTH"};
constexpr std::array<G, 1> kSpringGroups{{{"DEF", kSpringDef}}};

// ---- /TH/TRUSS: the axial force F (positive in tension), IE, the current area A, the initial length L (as the
// manual lists it) and the plastic strain PLAS (docs/theory/truss.md).
constexpr std::array<V, 6> kTruss{{{"OFF", "-", kNone, true},  {"F", "F", kForce, true},  {"IE", "E", kMoment, true},
                                   {"A", "L^2", kArea, true},  {"L", "L", kLength, true}, {"PLAS", "-", kNone, true}}};
constexpr std::array<S, 4> kTrussDef{"OFF", "F", "IE", "PLAS"};
constexpr std::array<G, 1> kTrussGroups{{{"DEF", kTrussDef}}};

// ---- /TH/BEAM: the resultants in the beam's frame on the face towards node 2, the moments at mid-length
// (docs/theory/beam.md, BM-2); DEF is all of them, as the manual.
constexpr std::array<V, 8> kBeam{{{"OFF", "-", kNone, true},     {"F1", "F", kForce, true},  {"F2", "F", kForce, true},
                                  {"F3", "F", kForce, true},     {"M1", "F L", kMoment, true}, {"M2", "F L", kMoment, true},
                                  {"M3", "F L", kMoment, true},  {"IE", "E", kMoment, true}}};
constexpr std::array<S, 8> kBeamDef{"OFF", "F1", "F2", "F3", "M1", "M2", "M3", "IE"};
constexpr std::array<G, 1> kBeamGroups{{{"DEF", kBeamDef}}};

constexpr HistoryKind kNodeKind{"NODE", kNode, kNodeGroups}, kPartKind{"PART", kPart, kPartGroups},
    kSubsetKind{"SUBS", kPart, kPartGroups}, kShellKind{"SHEL", kShell, kShellGroups},
    kSh3nKind{"SH3N", kShell, kShellGroups}, kBrickKind{"BRIC", kBrick, kBrickGroups},
    kInterfaceKind{"INTER", kInterface, kInterfaceGroups}, kWallKind{"RWALL", kWall, kWallGroups},
    kBodyKind{"RBODY", kBody, kBodyGroups}, kSectionKind{"SECTIO", kSection, kSectionGroups},
    kAccelerometerKind{"ACCEL", kAccelerometer, kAccelerometerGroups}, kSpringKind{"SPRING", kSpring, kSpringGroups},
    kTrussKind{"TRUSS", kTruss, kTrussGroups}, kBeamKind{"BEAM", kBeam, kBeamGroups};

const HistoryVariable* find_variable(const HistoryKind& kind, std::string_view name) {
  for (const HistoryVariable& v : kind.variables)
    if (v.name == name) return &v;
  return nullptr;
}

}  // namespace

const HistoryKind& history_kind(HistoryObject object) {
  switch (object) {
    case HistoryObject::Node: return kNodeKind;
    case HistoryObject::Part: return kPartKind;
    case HistoryObject::Subset: return kSubsetKind;
    case HistoryObject::Shell: return kShellKind;
    case HistoryObject::Sh3n: return kSh3nKind;
    case HistoryObject::Brick: return kBrickKind;
    case HistoryObject::Interface: return kInterfaceKind;
    case HistoryObject::RigidWall: return kWallKind;
    case HistoryObject::RigidBody: return kBodyKind;
    case HistoryObject::Section: return kSectionKind;
    case HistoryObject::Accelerometer: return kAccelerometerKind;
    case HistoryObject::Spring: return kSpringKind;
    case HistoryObject::Truss: return kTrussKind;
    case HistoryObject::Beam: return kBeamKind;
  }
  return kNodeKind;
}

HistorySelection select_history_variables(HistoryObject object, const std::vector<std::string>& requested) {
  const HistoryKind& kind = history_kind(object);
  HistorySelection selection;
  auto add = [&](const HistoryVariable* v) {
    if (std::find(selection.variables.begin(), selection.variables.end(), v) == selection.variables.end())
      selection.variables.push_back(v);
  };
  for (const std::string& name : requested) {
    if (const HistoryVariable* v = find_variable(kind, name)) {
      add(v);
      continue;
    }
    const auto group = std::find_if(kind.groups.begin(), kind.groups.end(),
                                    [&](const HistoryGroup& g) { return g.name == name; });
    if (group == kind.groups.end()) {
      selection.unknown.push_back(name);
      continue;
    }
    for (std::string_view member : group->members) add(find_variable(kind, member));
  }
  return selection;
}

std::vector<std::int32_t> objects_with_history(const Model& m, HistoryObject object,
                                               std::span<const std::string_view> variables) {
  std::vector<std::int32_t> objects;
  for (const TimeHistoryRequest& th : m.histories) {
    if (th.object != object) continue;
    const HistorySelection selection = select_history_variables(object, th.variables);
    const auto named = [&](const HistoryVariable* v) {
      return std::find(variables.begin(), variables.end(), v->name) != variables.end();
    };
    const bool asks = std::any_of(selection.variables.begin(), selection.variables.end(), named);
    if (asks) objects.insert(objects.end(), th.objects.begin(), th.objects.end());
  }
  std::sort(objects.begin(), objects.end());
  objects.erase(std::unique(objects.begin(), objects.end()), objects.end());
  return objects;
}

double si_factor(const Dimension& d, const double (&work_si)[3]) {
  const int exponents[3] = {d.mass, d.length, d.time};
  double f = 1.0;
  for (int i = 0; i < 3; ++i)
    if (exponents[i] != 0) f *= std::pow(work_si[i], exponents[i]);
  return f;
}

}  // namespace crumple
