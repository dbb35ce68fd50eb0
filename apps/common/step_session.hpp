#pragma once
/// \file step_session.hpp
/// The command interpreter behind fsi-step: one engine, commands in, one JSON object
/// out per command. Commands (words separated by blanks):
///   step [N]                  N time steps (default 1); stops early at a rejected step.
///                             The answer carries the last step's report ("last_report":
///                             Newton's residuals, factorizations, the largest residual's
///                             equation, node and place, seconds per stage, events)
///   render FILE.png [field=vx|vy|vmag|p|umag] [zoom=x0,y0,x1,y1] [size=WxH] [mesh=0|1]
///   functionals               the chapter's functionals of the current state
///   set KEY VALUE             a numerical parameter (any key of /numerics, e.g.
///                             time_step_s 1e-3, newton_budget 12, failure_policy halve_step),
///                             validated like a scenario file
///   numerics                  the numerical parameters in use
///   save FILE / load FILE     checkpoints (fsi::save_checkpoint / load_checkpoint)
///   remesh SCENARIO.json      the run goes on on that file's mesh (Engine::remesh_from);
///                             the rest of the file is ignored, the run's scenario kept
///   rereference               u measured from the ball moved with the body (Engine::rereference)
///   scenario FILE.json        writes the scenario in use (numerics as set, mesh as remeshed)
///   help                      the command list
///   quit                      ends the session
/// Answers: {"ok": true, "t": ..., "step": ..., ...} or {"error": "..."}; an error never
/// ends the session. Blank lines and lines starting with '#' get no answer.
#include <fsi/engine.hpp>
#include <fsi/renderer.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace fsi::app {

class StepSession {
 public:
  explicit StepSession(const Scenario& scenario);

  /// The answer to one command line; nullopt for blank and comment lines.
  std::optional<nlohmann::ordered_json> handle(const std::string& line);
  bool quit_requested() const { return quit_; }

  /// The one-line hint for people at a terminal.
  static const char* hint();

 private:
  nlohmann::ordered_json step(long n);
  nlohmann::ordered_json render(const std::vector<std::string>& words);
  nlohmann::ordered_json set(const std::string& key, const std::string& value);
  nlohmann::ordered_json ok() const;  ///< {"ok": true, "t": ..., "step": ...}

  Engine engine_;
  NumericsSpec numerics_;  ///< what set_numerics was last given
  long converged_ = 0, unconverged_ = 0;
  std::unique_ptr<render::Renderer> renderer_;  ///< made at the first render
  bool quit_ = false;
};

}  // namespace fsi::app
