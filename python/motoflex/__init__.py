"""motoflex: fit robot simulation parameters to recorded joint logs.

The native core (ODE physics, the MoToFlex servo pipeline, the evolution strategies) is the
extension module motoflex._motoflex; everything it offers is re-exported here:

    import motoflex
    scenario = motoflex.Scenario("scenarios/nao_default.yaml", duration_s=2.0)
    result = scenario.simulate({"motor.R_ohm": 6.5})    # dict of NumPy arrays
    summary = motoflex.fit("scenarios/fit/nao_quick.yaml", out="runs/q", max_generations=2,
                           progress=lambda p: print(p.line))
    motoflex.export("runs/q/best.json", "scenarios/robots/nao", "mjcf", "nao.xml")
"""

from ._motoflex import (  # noqa: F401  (the public API)
    FitBudget,
    FitProgress,
    FitSpec,
    FreeParameter,
    InputError,
    ModelError,
    Scenario,
    StrategyConfig,
    __version__,
    export,
    export_formats,
    fit,
    frequency_response,
    parameter_spread,
    read_log,
    read_parameters,
    resume,
    run_summary,
    simulate,
    write_log,
    write_parameters,
    write_report,
)


def rms_deg(result, joints=None):
    """RMS of measured minus commanded angle in degrees over a simulate() or read_log() dict,
    over all joints or the named ones."""
    import numpy as np

    names = list(result["joint_names"])
    columns = [names.index(j) for j in joints] if joints else list(range(len(names)))
    error = result["measured_rad"][:, columns] - result["commanded_rad"][:, columns]
    return float(np.degrees(np.sqrt(np.mean(error * error))))
