#!/usr/bin/env python3
"""Figures of the TITAN-VIII torque/power study (seed 000), from the files `motoflex titan`
writes into DIR:
  fig5_static_knee.png  J3 torque during static standing, feedback (eq. 4-5) and Jacobian (eq. 7)
  updown.png            body height and cumulative joint work vs potential energy
  fig8_torque.png       joint torques of one leg over one gait cycle, postures A-D
  fig9_power.png        joint powers of the same leg and cycle
  fig10_power.png       averaged absolute power (eq. 8) per posture

Usage: plot_titan.py DIR [--leg FL]
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from csv_columns import read_columns  # noqa: E402

LEGS = ["FL", "FR", "HL", "HR"]


def read_csv(path):
    return read_columns(path)[1]


def fig5(out, data, result):
    static = result["static"]
    touchdown = static.get("touchdown_s") or 0.0
    cut = touchdown + static.get("cut_after_touchdown_s", 0.03)
    t = data["time_s"]
    keep = [i for i, x in enumerate(t) if x >= cut]
    fig, axes = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for leg, alpha in zip(LEGS, [1.0, 0.35, 0.35, 0.35]):
        fb = data[leg + "_J3_feedback_nm"]
        jac = data[leg + "_J3_jacobian_nm"]
        axes[0].plot([t[i] - touchdown for i in keep], [fb[i] for i in keep], "-", color="C0",
                     alpha=alpha, label="feedback eq. 4-5" if leg == "FL" else None)
        axes[0].plot([t[i] - touchdown for i in keep], [jac[i] for i in keep], "--", color="C1",
                     alpha=alpha, label="Jacobian eq. 7" if leg == "FL" else None)
        if leg == "FL" and (leg + "_J4_feedback_nm") in data:
            ankle = data[leg + "_J4_feedback_nm"]
            axes[0].plot([t[i] - touchdown for i in keep], [fb[i] - ankle[i] for i in keep],
                         ":", color="k", lw=1.0, label="feedback minus ankle torque J4")
            axes[0].plot([t[i] - touchdown for i in keep], [ankle[i] for i in keep], "-",
                         color="C2", lw=0.8, label="ankle J4 torque (servo, k_d 1/s)")
        fz = data[leg + "_knee_fz_n"]
        axes[1].plot([t[i] - touchdown for i in keep], [fz[i] for i in keep], alpha=alpha,
                     label=leg)
    band = static.get("converge_band_nm", 0.5)
    final = static["knee_torque_feedback_nm"][0]
    for y in (final - band, final + band):
        axes[0].axhline(y, color="grey", lw=0.7, ls=":")
    axes[0].set_ylabel("J3 torque [N m]")
    axes[0].set_title("Static standing, knee J3 (FL bold, other legs faint); "
                      "converge: feedback %s s, Jacobian %s s" %
                      (fmt(static["feedback_converge_s"]), fmt(static["jacobian_converge_s"])),
                      fontsize=9)
    axes[0].legend(fontsize=8)
    axes[1].axhline(49.1, color="k", lw=0.7, ls=":", label="paper 49.1 N")
    axes[1].set_ylabel("knee Fz [N]")
    axes[1].set_xlabel("time after touchdown [s] (first %.0f ms cut)" %
                       (1000 * static.get("cut_after_touchdown_s", 0.03)))
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig5_static_knee.png"), dpi=110)
    plt.close(fig)


def fmt(value):
    return "never" if value is None else "%.3f" % value


def updown(out, data, result):
    u = result["updown"]
    t = data["time_s"]
    fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    axes[0].plot(t, data["body_height_m"])
    axes[0].set_ylabel("body height [m]")
    pe0 = data["potential_j"][0]
    axes[1].plot(t, [p - pe0 for p in data["potential_j"]], label="potential energy")
    axes[1].plot(t, data["work_feedback_j"], "--", label="joint work, feedback (all servos)")
    axes[1].plot(t, data["work_jacobian_j"], ":", label="joint work, Jacobian (J1-J3)")
    for ax in axes:
        for x in (u["rise_start_s"], u["rise_end_s"]):
            ax.axvline(x, color="grey", lw=0.7, ls=":")
    axes[1].set_ylabel("energy since start [J]")
    axes[1].set_xlabel("time [s]")
    axes[1].legend(fontsize=8)
    axes[0].set_title("Up-and-down: rise gain %.3f J, joint work %.3f J, period integral %.4f J" %
                      (u["potential_gain_j"], u["integrated_power_j"], u["period_integral_j"]),
                      fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "updown.png"), dpi=110)
    plt.close(fig)


def cycle_figure(out, cycles, leg, quantity, unit, name, title):
    postures = sorted(cycles)
    fig, axes = plt.subplots(len(postures), 1, figsize=(8, 2.3 * len(postures)), sharex=True,
                             squeeze=False)
    for ax, posture in zip(axes[:, 0], postures):
        data = cycles[posture]
        for j in range(3):
            ax.plot(data["cycle_time_s"], data["J%d_%s" % (j + 1, quantity)],
                    label="J%d" % (j + 1), lw=1.0)
        for x in (1.2, 2.4, 3.6):
            ax.axvline(x, color="grey", lw=0.6, ls="--")
        ax.axhline(0.0, color="k", lw=0.4)
        ax.set_ylabel("%s\n[%s]" % (posture, unit))
    axes[0, 0].legend(ncol=3, fontsize=8)
    axes[0, 0].set_title(title % leg, fontsize=9)
    axes[-1, 0].set_xlabel("time in the %s cycle [s] (swing 0-1.2 s; dashed: other legs' "
                           "touch-down)" % leg)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)


def fig10(out, result):
    crawl = result["crawl"]
    postures = [p for p in ["A", "B", "C", "D"] if p in crawl]
    fig, ax = plt.subplots(figsize=(7, 4))
    width = 0.2
    bottoms = [0.0] * len(postures)
    for j, color in zip(["J1_w", "J2_w", "J3_w"], ["C0", "C1", "C2"]):
        values = [crawl[p][j] for p in postures]
        ax.bar([i - width / 2 for i in range(len(postures))], values, width, bottom=bottoms,
               color=color, label=j[:2] + " (eq. 7)")
        bottoms = [b + v for b, v in zip(bottoms, values)]
    ax.bar([i + width / 2 for i in range(len(postures))],
           [crawl[p]["feedback"]["avg_abs_power_w"] for p in postures], width, color="grey",
           label="total, feedback eq. 4-5")
    for i, p in enumerate(postures):
        ax.text(i - width / 2, bottoms[i], "%.2f" % crawl[p]["avg_abs_power_w"], ha="center",
                va="bottom", fontsize=8)
    ax.set_xticks(range(len(postures)))
    ax.set_xticklabels(postures)
    ax.set_xlabel("walking posture")
    ax.set_ylabel("averaged absolute power |P| [W]")
    ax.set_title("Eq. 8 over %d periods, 4 legs x J1-J3, parallel-link knee" %
                 result["crawl_settings"]["periods"], fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig10_power.png"), dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dir")
    parser.add_argument("--leg", default="FL")
    args = parser.parse_args()
    with open(os.path.join(args.dir, "titan.json")) as f:
        result = json.load(f)
    fig5(args.dir, read_csv(os.path.join(args.dir, "static_knee.csv")), result)
    updown(args.dir, read_csv(os.path.join(args.dir, "updown.csv")), result)
    cycles = {}
    for posture in ["A", "B", "C", "D"]:
        path = os.path.join(args.dir, "crawl_%s_%s_cycle.csv" % (posture, args.leg))
        if os.path.exists(path):
            cycles[posture] = read_csv(path)
    if cycles:
        cycle_figure(args.dir, cycles, args.leg, "torque_nm", "N m", "fig8_torque.png",
                     "Joint torque of the %s leg over one cycle (eq. 7, parallel-link knee)")
        cycle_figure(args.dir, cycles, args.leg, "power_w", "W", "fig9_power.png",
                     "Joint power of the %s leg over one cycle (eq. 7, parallel-link knee)")
        fig10(args.dir, result)


if __name__ == "__main__":
    main()
