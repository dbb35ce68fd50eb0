#pragma once
/// \file engine.hpp
/// The engine: owns the discretization, the solver and the State; steps in time.
///
///   fsi::Engine engine(fsi::load_scenario("assets/scenarios/ball_drop.json"));
///   while (engine.state().time_s < engine.scenario().numerics.end_time_s) {
///     fsi::StepReport r = engine.step();
///     if (!r.converged) std::cerr << r.message << "\n";
///   }
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "fsi/field_view.hpp"
#include "fsi/scenario.hpp"
#include "fsi/state.hpp"

namespace fsi {

/// Something noteworthy that happened during a step.
struct StepEvent {
  /// degenerated: the step's solution broke the body (core/degeneration.hpp); it was not
  /// kept (retried shorter with FailurePolicy::halve_step, else rolled back).
  /// contact_force_active: the penalty contact force or a convex corner's barrier
  /// (ContactSpec::corner_barrier_speed_mps) pushed a body during the step.
  /// contact_retried: Newton did not converge in real contact, and the step was tried again
  /// at the same length with the wall's hold on the solid turned round (the contact patches
  /// held are released and the released held: core/contact_release.hpp).
  /// left_domain: the step's solution takes the body onto an open boundary of the domain,
  /// where the fixed mesh ends (core/degeneration.hpp, body_at_open_boundary); the step is
  /// rolled back at once, and the run cannot go on. Not a failure of the solver: where_m
  /// names the boundary point.
  enum class Kind { real_contact, contact_force_active, step_halved, rolled_back, non_finite, degenerated,
                    contact_retried, left_domain };
  Kind kind;
  double time_s = 0.0;
  Point2 where_m;          ///< place (contact: the interface point nearest the wall)
  int wall = -1;           ///< index into Scenario::walls (contact events)
  std::string text;
};

/// Where a step's final residual is largest, after row scaling (the step report's
/// diagnosis of a Newton stall: which equation, at which node, in which phase).
struct ResidualPeak {
  int node = -1;                ///< -1: no residual was measured
  Field equation = kVx;         ///< row kind: momentum x/y (kVx, kVy), displacement x/y, continuity (kP)
  Point2 where_m;               ///< the node's position in the step's (moved) mesh
  const char* phase = "";       ///< "fluid", "solid" or "interface" (node in both)
  double scaled_value = 0.0;    ///< |R_i| / max_j |J_ij| (the last factorization's J), as residual_norms
};

/// The equation a row of the system belongs to, in words ("momentum x", ...).
const char* equation_name(Field row);

/// What one call of Engine::step() did.
struct StepReport {
  bool converged = false;
  bool accepted = false;          ///< state advanced (false: rolled back)
  int newton_iterations = 0;
  int factorizations = 0;
  /// Jacobian assemblies: one per factorization, and with GMRES also the new Jacobians it
  /// solves with an older factorization (assembly_seconds is their time with the residuals').
  int jacobian_assemblies = 0;
  /// GMRES iterations (numerics.krylov_iterations > 0), one solve with a factorization each.
  int krylov_iterations = 0;
  std::vector<double> residual_norms;  ///< scaled residual before each iteration and at the end
  double time_step_s = 0.0;
  double time_s = 0.0;            ///< time after the step
  /// The estimated local error of the step in the body's position [m]
  /// (numerics.time_error_tolerance_m); negative where none was estimated.
  double time_error_m = -1.0;
  // Wall-clock seconds spent in each stage of the step.
  double geometry_seconds = 0.0;      ///< cut meshes, level set
  double mapping_seconds = 0.0;       ///< IPS Newton (12.4), T_m, old values
  double assembly_seconds = 0.0;
  double factorization_seconds = 0.0;
  double solve_seconds = 0.0;
  ResidualPeak largest_residual;      ///< of the attempt that was accepted (or the last)
  std::vector<StepEvent> events;
  std::string message;            ///< human-readable summary (failure reason if any)
};

class Engine {
 public:
  explicit Engine(Scenario scenario);
  ~Engine();
  Engine(Engine&&) noexcept;
  Engine& operator=(Engine&&) noexcept;
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  /// One time step: at most scenario().numerics.newton_budget Newton iterations
  /// (times the halvings allowed by the failure policy).
  StepReport step();

  const State& state() const;
  /// Restore a state saved from an engine of the same scenario.
  void set_state(const State& state);
  /// Continues `source`'s run on this engine's mesh (remeshing: a run goes on on a better
  /// mesh without starting again). This engine's scenario must be the source's up to
  /// `mesh` (throws InputError otherwise, and when a node lies outside the old mesh).
  /// Fields are interpolated node by node; the interface is rebuilt on the new mesh from
  /// the displacement that built it on the old one. Time and step number carry over.
  /// Where both meshes have the same nodes the fields are the same; the next steps are
  /// not bit-identical to the source's (the previous level's interface is approximated
  /// by the current one, see core/engine.cpp).
  void remesh_from(const Engine& source);
  /// Re-references the body now, whatever numerics.rereference_angle_rad says: u of both
  /// levels is measured from the initial ball moved and turned with the body (its
  /// least-squares rigid motion), State::reference_* record that. The interface, stresses
  /// and velocities stay as they are (core/rereference.hpp). Returns the angle taken out
  /// [rad] (0 when there is no solid node to fit). With several bodies (which the engine
  /// re-references after every step anyway) each body is, State::body_references records
  /// it, and the angle is body1's.
  double rereference();
  /// Change a numerical parameter between steps (time step, Newton budget, ...).
  /// scenario() reports the new numerics, and checkpoints saved afterwards carry them.
  void set_numerics(const NumericsSpec& numerics);

  /// Copy of the current mesh and fields for renderers and exporters.
  FieldView view() const;
  const Scenario& scenario() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Writes the state with a format version and the scenario fingerprint.
void save_checkpoint(const Engine& engine, const std::filesystem::path& file);
/// Restores a checkpoint into an engine; throws InputError if the checkpoint belongs
/// to another scenario (physics or discretization: the solver controls -- Newton budget,
/// tolerances, failure policy -- may differ) or format version.
void load_checkpoint(Engine& engine, const std::filesystem::path& file);

}  // namespace fsi
