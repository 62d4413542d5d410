#pragma once
// Properties (/PROP) and the global element defaults (/DEF_SHELL, /DEF_SOLID). The flags keep the values the
// deck gave (0 = default); the model build resolves them into the effective formulation fields.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "crumple/core/source_location.hpp"

namespace crumple {

// The shells' damping defaults where the property leaves them blank (docs/theory/shell4.md, S-9d, S-14; time-step.md,
// T-1c): the QEPH shell's numerical damping dn, and the membrane damping dm of the 3-node shell of a QEPH property and
// of the QEPH shell with /MAT/PLAS_TAB, as the reference runs them.
inline constexpr double kDefaultQephNumericalDamping = 0.015;
inline constexpr double kDefaultMembraneDamping = 0.015;
inline constexpr double kDefaultQbatNumericalDamping = 0.001;  // Ishell 12 (QBAT)

struct ShellSection {  // /PROP/TYPE1 (= /PROP/SHELL); flags and checks: docs/theory/shell4.md, "Formulation flags"
  int ishell = 0;          // 4-node formulation: 1, 2, 3 (Q4 hourglass variants), 12 QBAT, 24 QEPH (default)
  int ismstr = 0;          // small-strain flag: 1 from t = 0, 2 switchable (default), 4 never; 3 as 2
  int ish3n = 0;           // 3-node formulation: 1 or 2 (default 2); 30, 31 only without triangles
  int idrill = 0;          // drilling dof flag: 0 or 2 (none)
  double hm = 0.0, hf = 0.0, hr = 0.0;  // membrane, flexural, rotational hourglass coefficients
  double dm = 0.0, dn = 0.0;            // membrane and numerical damping
  int n_points = 0;        // integration points through the thickness (0 -> default)
  int istrain = 0;         // strain output flag (output only)
  double thickness = 0.0;  // [L], > 0
  double ashear = 0.0;     // shear factor (0 -> 5/6)
  int ithick = 0;          // thickness change flag
  int iplas = 0;           // plane-stress plasticity algorithm flag
  SourceLocation flags_where;    // the card's lines (Ishell ... line, hm ... line, N ... line), for errors
  SourceLocation damping_where;  // found when resolving the flags against the elements that use the property
  SourceLocation section_where;
};

struct SolidSection {  // /PROP/TYPE14 (= /PROP/SOLID), the values as written (0 = default)
  int isolid = 0;  // brick formulation (docs/theory/brick8.md, "Formulations")
  int ismstr = 0;  // small-strain flag
  int icpre = 0;   // constant (reduced) pressure flag: 1 on, 3 off, 2 plasticity dependent
  int iframe = 0;  // element frame: 1 non co-rotational, 2 co-rotational
  int inpts = 0;   // integration points ijk for Isolid 14
  double qa = 0.0, qb = 0.0;  // bulk viscosity coefficients (0 -> 1.1 and 0.05)
  double qa_or_default() const { return qa > 0.0 ? qa : 1.1; }
  double qb_or_default() const { return qb > 0.0 ? qb : 0.05; }
  double dn = 0.0;            // numerical damping of the Isolid 24 stabilisation (0 -> 0.1)
  double h = 0.0;             // hourglass coefficient (0 -> 0.1)
  int ihkt = 0;               // Isolid 24 hourglass modulus: 0, 1 elastic (2, tangent, is refused)
};

// The law of one degree of freedom of a spring (docs/theory/spring.md): a /PROP/TYPE4 spring has one, along its two
// nodes; a /PROP/TYPE8 spring six, in the global axes (X, Y, Z, then the rotations XX, YY, ZZ). The reader refuses
// the options Crumple lacks (sensors, some hardening flags).
struct SpringLaw {
  double stiffness = 0.0;  // K, the linear loading and unloading stiffness [F/L] or [F L/rad]; with a function, its step only
  double damping = 0.0;    // C, the viscous damping [F T/L] or [F L T/rad]
  // fct_ID1: the force A f(delta / Ascale) of a nonlinear elastic spring (H 0), eq. SP-2b; 0: K delta.
  std::int64_t function_id = 0;
  std::int32_t function = -1;  // dense index (model build)
  double function_scale = 1.0;     // A, times the input force unit [F]
  double abscissa_scale = 1.0;     // Ascale, in the input length unit [L]
  int hardening = 0;  // H: 0 elastic (on the function), 1 isotropic, 2 uncoupled, 4 kinematic (SP-6 to SP-8)
  std::int64_t lower_function_id = 0;  // fct_ID3: the lower yield curve of kinematic hardening (H 4)
  std::int32_t lower_function = -1;
  double delta_min = -1e30, delta_max = 1e30;  // the elongations that break it (0 or blank: never) [L]; with
                                                // Ifail2, forces [F] or energies [E] (SP-5b)
  // TYPE13's failure line of this degree of freedom (with Ifail2 >= 1, SP-5b): the limit raised by c (|rate| / V)^n,
  // and the criterion's weight alpha and exponent beta.
  double rate_c = 0.0, rate_n = 1.0, alpha = 1.0, beta = 2.0;
  // The rate effects (SP-23), r the elongation rate: the curve's force times R / A, R = A + B ln(max(1, |r| / D)) +
  // E g(r / F), and the force Hscale h(r / F) added. B and g act with fct_ID1 only (the reader drops them without).
  double log_rate = 0.0;            // B / A
  double log_rate_reference = 1.0;  // |D| (0 or blank: 1) [L/T] or [1/T]
  std::int64_t rate_factor_function_id = 0;  // fct_ID2: g, a factor of the rate (0: none)
  std::int32_t rate_factor_function = -1;
  double rate_factor_scale = 1.0;   // E / A (E 0 or blank: 1)
  double rate_scale = 1.0;          // F, the rate that g and h read in (0 or blank: 1) [L/T] or [1/T]
  std::int64_t rate_force_function_id = 0;  // fct_ID4: h, a force of the rate (0: none)
  std::int32_t rate_force_function = -1;
  double rate_force_scale = 1.0;    // Hscale, times the input force unit (0 or blank: 1) [F]
  bool acts() const {
    return stiffness > 0.0 || damping > 0.0 || function_id != 0 || rate_force_function_id != 0;
  }
};

inline constexpr int kSpringDofs = 6;  // the most a spring has: three translations, three rotations

// Where a spring's laws act (docs/theory/spring.md): /PROP/TYPE4 (= /PROP/SPRING), one law along its two nodes;
// /PROP/TYPE8 (= /PROP/SPR_GENE), six in the global axes; /PROP/TYPE13 (= /PROP/SPR_BEAM), six in a frame that
// turns with the spring, shear and bending coupled as a beam's.
enum class SpringFrame : std::uint8_t { Axial, Global, Beam };

// How a general or beam-type spring fails (Ifail, Ifail2; docs/theory/spring.md, SP-5b). Each law's value x (its
// elongation, its force or the work done on it) against its limit: Ifail 0 breaks the spring when one law reaches
// alpha x / lim >= 1, Ifail 1 when the sum of alpha (x / lim)^beta does.
enum class SpringFailureMeasure : std::uint8_t { Elongation, Force, Energy };
struct SpringFailure {
  bool combined = false;  // Ifail 1
  SpringFailureMeasure measure = SpringFailureMeasure::Elongation;
  bool rate_effect = false;  // TYPE13 with Ifail2 >= 1: the limits raised by the rate, alpha and beta from its lines
  double translation_rate = 1.0, rotation_rate = 1.0;  // Vo [L/T], Wo [1/T] (0 or blank: 1)
};

// /PROP/TYPE32 (/PROP/SPR_PRE): the pretensioner, a 1-D spring of stiffness K0 (dof[0]) that, once its sensor is
// on, holds at least the pretension F1 - K1 delta while its shortening delta since then is within the stroke
// D1 = F1 / K1 (docs/theory/spring.md, SP-22). F1, D1, E1, K1 resolved from the two the card gives.
struct SpringPretension {
  bool on = false;
  std::int64_t sensor_id = 0;  // sens_ID; 0: active from the start
  double activation_time = 0.0;  // [T] the sensor's Tdelay (resolved; 0 without a sensor)
  bool lock = false;           // Ilock 2: a plain K0 spring for good once the spring holds more than the pretension
  double force = 0.0;          // F1 [F]
  double energy = 0.0;         // E1 [E]: the spring's internal energy at t = 0 is |E1| (measured)
  double stiffness = 0.0;      // K1 [F/L]; the stroke D1 = F1 / K1
  // Function mode (fct_ID1, fct_ID2; SP-22b): the pretension Sf f1(-delta / Sd) f2((t - Tdelay) / St), a function
  // not given counting as 1; F1, E1 and K1 unused, D1 the stroke (0: none).
  std::int64_t stroke_function_id = 0, time_function_id = 0;
  std::int32_t stroke_function = -1, time_function = -1;  // dense indices (model build)
  double stroke_scale = 1.0, time_scale = 1.0, force_scale = 1.0;  // Sd [L], St [T], Sf [F] (0 or blank: 1)
  double stroke = 0.0;  // |D1| [L]
  bool by_functions() const { return stroke_function_id != 0 || time_function_id != 0; }
};

// sens_ID, Isflag (docs/theory/spring.md, SP-24): a spring switched by a /SENSOR/TIME. Isflag 0: off until the first
// cycle the sensor is on, then on for good; 1: on until then, then gone; 2: on while the sensor is, its rest length
// taken anew when it comes on (TYPE4).
struct SpringSwitch {
  std::int64_t sensor_id = 0;  // 0: always on
  int flag = 0;                // Isflag
  double on = 0.0, off = 1e300;  // the sensor's window (resolved) [T]
};

// /PROP/TYPE45 (/PROP/KJOINT2): a joint between two rigid bodies (docs/theory/spring.md, SP-25), a general spring of
// no mass whose blocked degrees of freedom are held by the stiffness the engine computes at its first step from the
// bodies' masses and inertias (Kn 0), damped at Cr of critical; its free ones each their own linear law.
struct SpringJoint {
  bool on = false;
  int type = 1;                    // Type 1 to 9 (SP-25g: which degrees of freedom each leaves free)
  double blocking_stiffness = 0.0;  // Kn [F/L]: 0 the automatic stiffness of SP-25c, d; given, SP-25i
  double stiffness_scale = 1.0;     // ScF (0 or blank: 1, or 10 with a given Kn, where it scales the rotations' only)
  double critical_damping = 0.05;  // Cr (0 or blank: 0.05), of the blocked degrees of freedom only (measured)
  std::int64_t skew_id = 0;        // Skew_ID1: a /SKEW/FIX that sets the frame where node_ID3 is not given (SP-25f)
  std::int32_t skew = -1;          // its dense index (model build)
  // Degree of freedom d (0-2 the translations, 3-5 the rotations in the joint's frame) is free: its own law acts
  // (SP-25g, one bit per degree of freedom and type: 1 spherical, 2 revolute, 3 cylindrical, 4 planar, 5 universal,
  // 6 translational, 7 Oldham, 8 rigid, 9 free).
  bool free(std::size_t d) const { return (kFreeDofs[static_cast<std::size_t>(type)] >> d) & 1u; }
  // The /SPRING card's nodes that set the joint's frame without a skew (SP-25f): node_ID3 for every type but the
  // spherical and the rigid, node_ID4 as well for the universal and the free joint.
  int frame_nodes() const {
    if (skew_id != 0) return 0;
    return universal() || type == 9 ? 2 : type == 1 || type == 8 ? 0 : 1;
  }
  // The universal joint (Type 5): its frame's Y is body 1's, its Z body 2's (SP-25f).
  bool universal() const { return type == 5; }
  static constexpr unsigned kFreeDofs[10] = {0, 0b111000, 0b001000, 0b001001, 0b001110, 0b110000, 0b000001, 0b000110, 0,
                                             0b111111};
  static bool supported(int type) { return type >= 1 && type <= 9; }
};

struct SpringSection {
  double mass = 0.0;     // M, the spring's mass, half at each node [M]; > 0 (the reference refuses 0)
  double inertia = 0.0;  // TYPE8 and TYPE13: its rotational inertia, half at each node [M L^2]
  SpringFrame frame = SpringFrame::Axial;
  std::array<SpringLaw, kSpringDofs> dof;  // TYPE4: dof[0] only
  std::int64_t skew_id = 0;  // TYPE13: the skew whose Y orients the frame at rest (SP-15); 0: global Y
  std::int32_t skew = -1;
  // TYPE25: the beam-type spring whose shear (dof[1] = dof[2]) and bending (dof[4] = dof[5]) are each one law of the
  // magnitude of the radial displacement or rotation (docs/theory/spring.md, SP-20).
  bool radial = false;
  // Ileng 1 (TYPE4, TYPE13): the mass, inertia, stiffnesses and dampings per unit length, the curves of the strain
  // delta / L0 (docs/theory/spring.md, SP-21); each spring's own values follow from its rest length.
  bool per_unit_length = false;
  SpringPretension pretension;  // TYPE32
  SpringSwitch sensor;          // TYPE4, TYPE8, TYPE13
  SpringFailure failure;  // TYPE8, TYPE13, TYPE25 (TYPE4: Ifail 0 on the elongation)
  SpringJoint joint;      // TYPE45
  int dofs() const { return frame == SpringFrame::Axial ? 1 : kSpringDofs; }
  std::string_view card() const {  // /PROP/<card>
    if (radial) return "SPR_AXI";
    if (pretension.on) return "SPR_PRE";
    if (joint.on) return "KJOINT2";
    return frame == SpringFrame::Axial ? "SPRING" : frame == SpringFrame::Global ? "SPR_GENE" : "SPR_BEAM";
  }
};

// /PROP/TYPE2 (= /PROP/TRUSS): a truss's cross-section (docs/theory/truss.md).
struct TrussSection {
  double area = 0.0;  // Area, the initial cross-section [L^2]; > 0
  double gap = 0.0;   // Gap_ini: the truss acts only once shortened by more than this (TR-5); 0: always [L]
};

// /PROP/TYPE3 (= /PROP/BEAM): a beam's section (docs/theory/beam.md).
struct BeamSection {
  int ismstr = 0;        // 0: the axial strain logarithmic and the step on the current length; 1: on L0 (BM-1, BM-8)
  double dm = 0.0;       // membrane numerical damping as written (BM-7)
  double df = 0.0;       // flexural numerical damping as written; 0 or blank: 0.01 (BM-7)
  double area = 0.0;     // A [L^2] > 0
  double iyy = 0.0, izz = 0.0, ixx = 0.0;  // second moments about local y and z, polar [L^4] > 0
  int ishear = 0;        // 0: Timoshenko's shear (k = 5/6); 1: none, Euler-Bernoulli (BM-3)
  double df_or_default() const { return df != 0.0 ? df : 0.01; }
};

enum class PropertyKind : std::uint8_t { Shell, Solid, Spring, Truss, Beam };
inline constexpr int kPropertyKinds = 5;

// What a property kind is, as data: its keyword's two names and whether it carries the law (a part of it needs
// no material: mat_ID 0).
struct PropertyKindDescription {
  PropertyKind kind;
  std::string_view name;  // /PROP/<name>: SHELL, SOLID, SPRING
  std::string_view card;  // /PROP/TYPE1, /PROP/TYPE14, /PROP/TYPE4
  std::string_view what;  // the messages' word: "shell"
  bool carries_law;
};
inline constexpr PropertyKindDescription kPropertyKindTable[kPropertyKinds] = {
    {PropertyKind::Shell, "SHELL", "/PROP/TYPE1", "shell", false},
    {PropertyKind::Solid, "SOLID", "/PROP/TYPE14", "solid", false},
    {PropertyKind::Spring, "SPRING", "/PROP/TYPE4", "spring", true},
    {PropertyKind::Truss, "TRUSS", "/PROP/TYPE2", "truss", false},
    {PropertyKind::Beam, "BEAM", "/PROP/TYPE3", "beam", false},
};
constexpr const PropertyKindDescription& describe(PropertyKind kind) {
  return kPropertyKindTable[static_cast<int>(kind)];
}

struct Property {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  PropertyKind kind = PropertyKind::Shell;
  ShellSection shell;
  SolidSection solid;
  SpringSection spring;
  TrussSection truss;
  BeamSection beam;
};

struct ShellDefaults {  // /DEF_SHELL
  int ishell = 0, ismstr = 0, ithick = 0, iplas = 0, istrain = 0, ish3n = 0, idrill = 0;
  SourceLocation where;  // its data line (none: where.line == 0)
};
struct SolidDefaults {  // /DEF_SOLID
  int isolid = 0, ismstr = 0, icpre = 0, istrain = 0, iframe = 0;
  SourceLocation where;  // its data line (none: where.line == 0)
};

// Effective element formulations after property, /DEF_SHELL or /DEF_SOLID and the built-in defaults.
struct ResolvedFormulation {
  int ishell = 24;  // 4-node shells: 1 or 24
  int ish3n = 2;    // 3-node shells: 1 or 2
  int isolid = 1;   // bricks: 1, 14 or 24
  int icpre = 0;    // bricks: 1 constant pressure, 2 its plasticity-following share (B-9c), 3 none (0: Isolid 1)
  int iframe = 1;   // bricks: 1 non co-rotational, 2 co-rotational
  int ismstr = 0;   // small-strain flag after /DEF_SHELL or /DEF_SOLID (shells: 1, 2 or 4)
  int n_points = 0; // shells: through-thickness points; 0 = global (stress-resultant) plasticity
  int iplas = 2;    // shells, plastic points: 1 the iterative (exact) plane-stress return, 2 the radial return
};

// Bricks integrated at 2x2x2 points (Isolid 12, 14, 17, 18); 1, 2 and 24 take one point (docs/theory/brick8.md).
inline bool fully_integrated_brick(int isolid) { return isolid != 1 && isolid != 2 && isolid != 24; }

// The factor a viscous fraction nu takes off an element's critical step, sqrt(1 + nu^2) - nu (docs/theory/
// time-step.md, eq. T-1c): the stable step of a damped oscillator, 0.98511 for nu = 0.015.
inline double damped_step_factor(double nu) { return std::sqrt(1.0 + nu * nu) - nu; }

// The 3-node shell's membrane damping dm (docs/theory/shell4.md, S-9d): as given; blank, 0.015 when the property's
// 4-node formulation resolves to QEPH (Ishell 24) and 0 otherwise, as the reference runs it.
inline double triangle_membrane_damping(const ShellSection& s, const ResolvedFormulation& f) {
  return s.dm > 0.0 ? s.dm : f.ishell == 24 ? kDefaultMembraneDamping : 0.0;
}
// The QEPH shell's (Ishell 24) membrane damping dm and numerical damping dn (S-9d, S-14): as given; blank, both
// 0.015 with every law, as the reference resolves them (measured with /MAT/ELAST, /MAT/PLAS_JOHNS, /MAT/PLAS_TAB).
inline double qeph_membrane_damping(const ShellSection& s) { return s.dm > 0.0 ? s.dm : kDefaultMembraneDamping; }
inline double qeph_numerical_damping(const ShellSection& s) { return s.dn > 0.0 ? s.dn : kDefaultQephNumericalDamping; }
// The QBAT shell's (Ishell 12) numerical damping dn: as given; blank, 0.001 (its nodal step under /DT/NODA/CST follows
// it as the reference's does, T-2b).
inline double qbat_numerical_damping(const ShellSection& s) { return s.dn > 0.0 ? s.dn : kDefaultQbatNumericalDamping; }

// The viscous fraction that shortens a one-point shell's critical step (eq. T-1c): dm, and for the QEPH shell
// (physical hourglass) the larger of dm and dn. The kernels and the model's initial steps take it.
inline double shell_step_damping(bool physical_hourglass, double dm, double dn) {
  return physical_hourglass ? std::max(dm, dn) : dm;
}

// The viscous fractions a shell runs with, as its formulation takes them: the one definition the kernels' set-up,
// `crumple check` and the listing's steps read.
struct ShellDamping {
  double membrane = 0.0;   // dm, the membrane damping (S-9d)
  double numerical = 0.0;  // dn: on QEPH's hourglass modes (S-14), on QBAT's resultants; 0 for the others
  double step = 0.0;       // the fraction that shortens the element's critical step (T-1c)
};
inline ShellDamping shell_damping(bool triangle, const ShellSection& s, const ResolvedFormulation& f) {
  if (triangle) {
    const double dm = triangle_membrane_damping(s, f);
    return {dm, 0.0, shell_step_damping(false, dm, 0.0)};
  }
  if (f.ishell == 24) {
    const double dm = qeph_membrane_damping(s), dn = qeph_numerical_damping(s);
    return {dm, dn, shell_step_damping(true, dm, dn)};
  }
  if (f.ishell == 12) return {0.0, qbat_numerical_damping(s), 0.0};
  // Ishell 1 to 4: a given dm acts (S-9d; measured on the reference, shell4.md "Probes").
  return {s.dm, 0.0, shell_step_damping(false, s.dm, 0.0)};
}

}  // namespace crumple
