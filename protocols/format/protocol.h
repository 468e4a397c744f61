// The Protocol data model: what a protocol file says, validated and in SI, as plain structs (no
// toml++ type leaks out). Every value keeps the SourceLocation it was read from (line 0 for a
// default), so scenario assembly can report its own errors at the line the user wrote.
// The file format itself is documented in docs/protocols.md; the keys, units and ranges are in
// parameter_table.cpp, the single source of the loader, the validator and that document.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "protocols/format/source_location.h"

namespace protocols {

inline constexpr int kProtocolFormatVersion = 1;

// Each enum's names, in enum order: the parser maps a name to its index, so the file names a
// method and never a number (docs/developer-guide.md code rule 7).
enum class EyeKind { kEmmetropic, kMyopic, kStaphyloma, kMesh };
inline constexpr std::array<std::string_view, 4> kEyeKindNames = {"emmetropic", "myopic",
                                                                  "staphyloma", "mesh"};
enum class EyeSide { kOd, kOs };  // OD = right eye, OS = left eye
inline constexpr std::array<std::string_view, 2> kEyeSideNames = {"OD", "OS"};
enum class DistanceReference { kLimbus, kOraSerrata };
enum class TissueMode { kAuto, kElastic, kRigid };
inline constexpr std::array<std::string_view, 3> kTissueModeNames = {"auto", "elastic", "rigid"};
enum class Anchoring { kNone, kOuterSurface, kBackFace };
inline constexpr std::array<std::string_view, 3> kAnchoringNames = {"none", "outer_surface",
                                                                    "back_face"};
enum class ViscosityKind { kDynamic, kKinematic };
enum class PostureName { kSupine, kFaceDown, kUpright, kLeftSide, kRightSide, kCustom };
inline constexpr std::array<std::string_view, 5> kPostureNames = {"supine", "face-down", "upright",
                                                                  "left-side", "right-side"};
enum class EffectSetting { kAuto, kOn, kOff };
enum class AccuracyPreset { kDraft, kStandard, kFine };
inline constexpr std::array<std::string_view, 3> kAccuracyPresetNames = {"draft", "standard",
                                                                         "fine"};
// Discretisation of the interfacial surface stress (sim's SurfaceStressForm).
enum class SurfaceStressName { kAuto, kCorrected, kSymmetric };
inline constexpr std::array<std::string_view, 3> kSurfaceStressNames = {"auto", "corrected",
                                                                        "symmetric"};
// The cavity wall's particles (protocols/assembly/layered_cavity_walls.h): "layered" three
// lattice layers behind the mesh (the fluid fills the cavity up to it), "single_layer" one
// Akinci layer on the mesh; "auto" layered unless an elastic tissue replaces part of the wall.
enum class WallModelName { kAuto, kLayered, kSingleLayer };
inline constexpr std::array<std::string_view, 3> kWallModelNames = {"auto", "layered",
                                                                    "single_layer"};
// Where a simulated schedule's fluid starts (protocols/equilibrium/start_from_equilibrium.h):
// "fill_plane" the oil above a flat plane at the fill level, "equilibrium" the oil where the first
// posture's static equilibrium puts it, so the run spends no time relaxing a flat fill.
enum class StartName { kFillPlane, kEquilibrium };
inline constexpr std::array<std::string_view, 2> kStartNames = {"fill_plane", "equilibrium"};
// Tamponade agents of the material library (anatomy's data/materials), plus "custom".
inline constexpr std::array<std::string_view, 6> kTamponadeAgentNames = {
    "silicone_oil_1000", "silicone_oil_5000",  "densiron_68",
    "oxane_hd",          "perfluoro_n_octane", "custom"};
inline constexpr std::string_view kCustomAgent = "custom";
// Tissue materials of the material library.
inline constexpr std::array<std::string_view, 2> kTissueMaterialNames = {"sclera", "orbital_fat"};
// The solvers and the effects a protocol may name come from the engine's registries
// (protocols/format/stage_names.h).
inline constexpr std::string_view kDefaultSolver = "indsph";  // the format's default

struct RetinalBreak {
  Located<std::string> name;
  Located<double>
      clockHour;  // [h] as the surgeon sees the fundus, 1 <= h < 13 (12.5 = half past 12)
  DistanceReference reference = DistanceReference::kLimbus;
  Located<double> distance;  // [m] along the wall, posterior to `reference`
  Located<double> diameter;  // [m]
  SourceLocation where;      // the [[eye.breaks]] header
};

struct TissueSpec {
  Located<std::string> material;                 // a tissue of the material library
  std::optional<Located<double>> youngsModulus;  // [Pa] overrides the material
  std::optional<Located<double>> poissonRatio;   // [1] overrides the material
  std::optional<Located<double>> density;        // [kg/m^3] overrides the material
  std::optional<Located<double>> thickness;  // [m] sclera only: overrides the anatomical profile
  Located<TissueMode> mode;                  // auto = elastic only if it would deform
  Located<Anchoring> anchoring;
  SourceLocation where;  // the [eye.sclera] / [eye.orbital_fat] header
};

struct MeshSource {
  Located<std::filesystem::path> path;  // resolved against the protocol file's folder
  std::string pathAsWritten;
  Located<std::string> units;  // "mm", ... as written
  double metresPerUnit = 1.0;  // [m] length of one mesh unit
};

struct EyeSpec {
  Located<EyeKind> kind;
  Located<EyeSide> side;
  std::optional<Located<double>> axialLength;      // [m]; absent = anatomy's default for the kind
  std::optional<Located<double>> staphylomaDepth;  // [m] kind = staphyloma
  std::optional<Located<double>> staphylomaWidth;  // [m] kind = staphyloma
  std::optional<MeshSource> mesh;                  // kind = mesh
  std::vector<RetinalBreak> breaks;
  std::optional<TissueSpec> sclera;
  std::optional<TissueSpec> orbitalFat;
};

struct Viscosity {
  double value = 0.0;  // [Pa s] if kDynamic, [m^2/s] if kKinematic (mu = rho nu converts later)
  ViscosityKind kind = ViscosityKind::kDynamic;
};

struct TamponadeSpec {
  Located<std::string> agent;  // a name of kTamponadeAgentNames
  Located<double> fill;        // [1] fraction of the cavity volume, in (0, 1]; the rest is aqueous
  // For "custom" all four are present; for a library agent each present one overrides it.
  std::optional<Located<double>> density;  // [kg/m^3]
  std::optional<Located<Viscosity>> viscosity;
  std::optional<Located<double>> interfacialTension;  // [N/m] against aqueous
  std::optional<Located<double>> contactAngle;        // [rad] on retina, THROUGH THE AQUEOUS phase
  bool isCustom() const { return agent.value == kCustomAgent; }
};

struct Posture {
  Located<PostureName> name;                        // kCustom when given as a gravity direction
  Located<std::string> label;                       // the user's label, else the name or "custom"
  Located<std::array<double, 3>> gravityDirection;  // [1] unit vector, eye frame; kCustom only
  bool untilSteady = false;
  // duration = "equilibrium": the posture's static equilibrium (sim/equilibrium/), not a
  // simulated time; `duration` is then kEquilibriumHold, its weight in the schedule's means.
  bool equilibrium = false;
  Located<double> duration;  // [s]; with untilSteady the upper bound
  SourceLocation where;      // the [[schedule.postures]] header
};

// [s] The weight of an equilibrium posture in the schedule's time means: each counts alike (the
// transients between postures are neglected; docs/methods/equilibrium.md).
inline constexpr double kEquilibriumHold = 1.0;

struct ScheduleSpec {
  Located<double> gravity;  // [m/s^2] magnitude
  std::vector<Posture> postures;
  // "until steady" postures (protocols/run/steady_state.h): the window [s] and the largest
  // coverage change [1] of any region or break within it.
  Located<double> steadyWindow;
  Located<double> steadyCoverageChange;
  Located<StartName> start;  // where the fluid starts (simulated postures)
};

struct EffectSwitches {
  // One per forceable effect, in effectSwitchNames() order. kAuto = inferred from the scene
  // (docs/developer-guide.md principle 1).
  std::vector<Located<EffectSetting>> settings;
  const Located<EffectSetting>& get(std::string_view effect) const;
};

struct AccuracySpec {
  Located<AccuracyPreset> preset;
  // Resolved: the preset's value unless the file gives one explicitly (then where.line > 0).
  Located<double> particleSpacing;  // [m]
  Located<double> solverTolerance;  // [1] relative density error the pressure solve stops at
  Located<double> minTimeStep;      // [s]
  Located<double> maxTimeStep;      // [s]
  Located<SurfaceStressName> surfaceStress;  // not part of the presets
  Located<WallModelName> wallModel;          // not part of the presets
};

// Preset values. Spacings give ~1e4 / 4e4 / 2e5 fluid particles in a 5 mL cavity; the
// tolerances (mean density error where every implicit pressure solve stops) stay well below the
// 3 % oil/aqueous density difference. Measured on the example eyes (docs/accuracy.md,
// `tamponade bench accuracy`): 0.5 % runs 3.6-3.9x faster than 0.01 % and moves the whole-retina
// coverage by one point; 0.1 % by 0.5.
struct AccuracyPresetValues {
  std::string_view name;
  double particleSpacing;  // [m]
  double solverTolerance;  // [1]
  double minTimeStep;      // [s]
  double maxTimeStep;      // [s]
};
inline constexpr std::array<AccuracyPresetValues, 3> kAccuracyPresets = {{
    {"draft", 0.8e-3, 5e-3, 1e-7, 2e-3},
    {"standard", 0.5e-3, 1e-3, 1e-7, 1e-3},
    {"fine", 0.3e-3, 5e-4, 1e-7, 5e-4},
}};

struct OutputsSpec {
  Located<std::string> folder;               // relative to the working directory of the run
  Located<double> frameInterval;             // [s] simulated time between frames
  std::vector<Located<std::string>> fields;  // particle field names, checked against the
                                             // field registry at scenario assembly
  Located<bool> report;
};

struct Protocol {
  std::filesystem::path file;  // as given to parseProtocol
  Located<int> formatVersion;
  std::optional<Located<std::string>> title;
  std::optional<Located<std::string>> description;
  Located<std::string> solver;  // a name of the solver registry
  EyeSpec eye;
  TamponadeSpec tamponade;
  ScheduleSpec schedule;
  EffectSwitches effects;
  AccuracySpec accuracy;
  OutputsSpec outputs;
};

// Name of an enum value (the inverse of what the parser reads).
std::string_view toString(EyeKind v);
std::string_view toString(EyeSide v);
std::string_view toString(TissueMode v);
std::string_view toString(Anchoring v);
std::string_view toString(PostureName v);  // "custom" for kCustom
std::string_view toString(EffectSetting v);
std::string_view toString(AccuracyPreset v);
std::string_view toString(SurfaceStressName v);
std::string_view toString(WallModelName v);
std::string_view toString(StartName v);
// The preset called `name` ("draft", "standard", "fine"), or nothing for any other name.
std::optional<AccuracyPreset> accuracyPresetFromName(std::string_view name);

}  // namespace protocols
