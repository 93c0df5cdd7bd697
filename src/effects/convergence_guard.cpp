#include "motoflex/effects/convergence_guard.hpp"

#include <filesystem>

#include "motoflex/core/error.hpp"

namespace motoflex {

std::string check_converged_for_ranking(const FinishedFit& fit, const std::string& run_dir,
                                        bool force, const std::string& command) {
  if (!fit.summary.is_object() || fit.summary.value("converged", true)) return {};
  const std::string why = fit.summary.value("convergence", std::string("not converged"));
  const std::string reason = "the fit did not converge (" + why + ")";
  if (force) return reason;
  throw InputError(
      (std::filesystem::path(run_dir) / "summary.json").string(), 0, "converged",
      reason + ": its residual mixes a missing effect with the optimiser's unfinished work, so " +
          command + " would rank effects unreliably. Continue it until it converges (motoflex " +
          "resume " + run_dir + " --max-evaluations N, or a larger budget in the fit config), " +
          "or pass --force to rank anyway (every ranking is then marked unreliable)");
}

}  // namespace motoflex
