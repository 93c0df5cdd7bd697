#!/usr/bin/env python3
"""BAM's pendulum simulation (Algorithm 1 of Duclusaud et al., ICRA 2025), written from its
description in ../shared/reference/bam.md §2a-2d, independently of motoflex's C++ bench law:
a second implementation that motoflex's XL330 numbers are checked against (probe_xl330.py).

Per 5 ms step of a processed log: the voltage P servo (duty = clip(error_gain*kp*(goal - q),
+-1), U = vin*duty with the header's nominal vin, tau_m = Kt*U/R - Kt^2*dq/R, zero while the
torque is off), the optional driver current limit (|I| <= I_max), gravity tau_e =
-m*g*l*sin(q + q_offset), friction budgets M1 (Coulomb + viscous) and M3 (+ K_l*|tau_m - tau_e|)
applied by clipping the stopping torque, and BAM's integrator. Vectorised over parameter sets x
logs; logs are cut to the shortest, as BAM's batch does.

Usage as a module: logs = load_logs(paths); mae_rad(params, logs) -> (sets, logs) array.
"""
import json

import numpy as np

G_M_S2 = 9.80665
XL330_ERROR_GAIN = 0.0028774  # (4096/2pi)/(256*885), bam.md §2c


# motoflex parameter name -> this module's (servo: bench, BAM's friction family)
MOTOFLEX_NAMES = {"bench.Kt_nm_per_a": "kt_nm_per_a", "bench.R_ohm": "r_ohm",
                  "bench.armature_kg_m2": "armature_kg_m2",
                  "joint.pendulum.friction_nm": "coulomb_nm",
                  "joint.pendulum.viscous_nm_s_per_rad": "viscous_nm_s_per_rad",
                  "joint.pendulum.load_friction": "load_friction",
                  "motor.current_limit_a": "current_limit_a"}


def from_motoflex(parameters):
    """One parameter set for simulate() from motoflex names (a best.json's parameters); names
    this module does not model are left out. The load friction is M3's: pass it only from a
    set with joint.pendulum.friction_model 3."""
    return {ours: [parameters[name]] for name, ours in MOTOFLEX_NAMES.items()
            if name in parameters}


def load_logs(paths):
    """BAM processed logs (JSON): header and per-sample arrays, cut to the shortest log."""
    logs = []
    for path in paths:
        with open(path) as f:
            log = json.load(f)
        entries = log["entries"]
        logs.append({
            "path": path, "kp": log["kp"], "mass_kg": log["mass"], "length_m": log["length"],
            "vin_v": log["vin"], "trajectory": log.get("trajectory", ""),
            "q_rad": np.array([e["position"] for e in entries]),
            "dq_rad_s": np.array([e["speed"] for e in entries]),
            "goal_rad": np.array([e["goal_position"] for e in entries]),
            "torque_on": np.array([1.0 if e["torque_enable"] else 0.0 for e in entries])})
    samples = min(len(log["q_rad"]) for log in logs)
    for log in logs:
        for key in ("q_rad", "dq_rad_s", "goal_rad", "torque_on"):
            log[key] = log[key][:samples]
    return logs


def simulate(params, logs, dt_s=0.005, error_gain=XL330_ERROR_GAIN, half_step_term=True):
    """Simulated positions (sets, logs, samples). params: name -> array (sets,) of kt_nm_per_a,
    r_ohm, armature_kg_m2, coulomb_nm, viscous_nm_s_per_rad and optionally load_friction (M3),
    current_limit_a, q_offset_rad. half_step_term: BAM's position update q += dq*dt + a*dt^2/2
    with the already updated dq (its position then leads by about dq*dt/2); False: q += dq*dt,
    the semi-implicit Euler step of ODE and so of motoflex."""
    sets = len(params["kt_nm_per_a"])
    p = {k: np.asarray(v, dtype=float)[:, None] for k, v in params.items()}
    header = {k: np.array([[log[k] for log in logs]]) for k in ("kp", "mass_kg", "length_m",
                                                                 "vin_v")}
    goal = np.stack([log["goal_rad"] for log in logs])
    torque_on = np.stack([log["torque_on"] for log in logs])
    kt, r = p["kt_nm_per_a"], p["r_ohm"]
    inertia = header["mass_kg"] * header["length_m"] ** 2 + p["armature_kg_m2"]
    weight_nm = header["mass_kg"] * G_M_S2 * header["length_m"]
    q = np.repeat(np.array([[log["q_rad"][0] for log in logs]]), sets, 0)
    dq = np.repeat(np.array([[log["dq_rad_s"][0] for log in logs]]), sets, 0)
    out = np.empty((sets, len(logs), goal.shape[1]))
    for t in range(goal.shape[1]):
        out[:, :, t] = q
        external_nm = -weight_nm * np.sin(q + p.get("q_offset_rad", 0.0))
        duty = np.clip(error_gain * header["kp"] * (goal[:, t] - q), -1.0, 1.0)
        current_a = (header["vin_v"] * duty - kt * dq) / r
        if "current_limit_a" in p:
            current_a = np.clip(current_a, -p["current_limit_a"], p["current_limit_a"])
        motor_nm = kt * current_a * torque_on[:, t]
        budget_nm = p["coulomb_nm"] + p["viscous_nm_s_per_rad"] * np.abs(dq)
        if "load_friction" in p:
            budget_nm = budget_nm + p["load_friction"] * np.abs(motor_nm - external_nm)
        net_nm = motor_nm + external_nm
        stop_nm = inertia / dt_s * dq + net_nm
        friction_nm = -np.sign(stop_nm) * np.minimum(np.abs(stop_nm), budget_nm)
        acceleration = (net_nm + friction_nm) / inertia
        dq = np.clip(dq + acceleration * dt_s, -100.0, 100.0)
        q = q + dq * dt_s + (0.5 * acceleration * dt_s * dt_s if half_step_term else 0.0)
    return out


def mae_rad(params, logs, **options):
    """Mean |q_logged - q_simulated| per parameter set and log (sets, logs)."""
    measured = np.stack([log["q_rad"] for log in logs])[None]
    return np.abs(simulate(params, logs, **options) - measured).mean(axis=2)
