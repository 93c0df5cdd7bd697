"""Tests of the Python module motoflex against the CLI: the same scenario, fit and export give
the same numbers bit for bit, a fit resumes exactly, Ctrl-C keeps the checkpoint, and errors
name the field. Run by ctest (python.ModuleTests) with PYTHONPATH=build/python,
MOTOFLEX_SOURCE_DIR and MOTOFLEX_BINARY set."""

import json
import os
import re
import subprocess
import tempfile
import unittest

import numpy as np

import motoflex

SOURCE = os.environ.get("MOTOFLEX_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("MOTOFLEX_BINARY", os.path.join(SOURCE, "build", "motoflex"))
NAO = os.path.join(SOURCE, "scenarios", "nao_default.yaml")
BENCH_FIT = os.path.join(SOURCE, "scenarios", "fit", "bench_hidden.yaml")
BENCH_SCENARIO = os.path.join(SOURCE, "scenarios", "bench", "chirp.yaml")
BENCH_TRAIN = os.path.join(SOURCE, "reference_data", "hidden", "none", "train")


def cli(*arguments):
    """Runs the motoflex binary; returns its stdout (raises on a non-zero exit)."""
    done = subprocess.run([BINARY, *arguments], capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise AssertionError(f"motoflex {' '.join(arguments)} exited {done.returncode}: {done.stderr}")
    return done.stdout


def best(run_dir):
    with open(os.path.join(run_dir, "best.json"), encoding="utf-8") as f:
        data = json.load(f)
    return data["fitness"], data["parameters"]


def generations_without_seconds(run_dir):
    with open(os.path.join(run_dir, "generations.csv"), encoding="utf-8") as f:
        return [line.rsplit(",", 1)[0] for line in f]


class SimulateTest(unittest.TestCase):
    def test_simulate_equals_the_cli_bit_for_bit(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "sim.csv")
            cli("simulate", NAO, "--duration", "0.4", "--out", out)
            from_cli = motoflex.read_log(out, need_measured=True)
        result = motoflex.simulate(NAO, duration_s=0.4)
        self.assertEqual(result["end"], "completed")
        self.assertEqual(list(result["joint_names"]), list(from_cli["joint_names"]))
        self.assertEqual(result["measured_rad"].shape, from_cli["measured_rad"].shape)
        self.assertTrue(np.array_equal(result["measured_rad"], from_cli["measured_rad"]))
        self.assertTrue(np.array_equal(result["time_s"], from_cli["time_s"]))

    def test_parameters_change_the_motion_and_unknown_names_are_named(self):
        scenario = motoflex.Scenario(NAO, duration_s=0.3)
        self.assertEqual(scenario.robot, "nao")
        nominal = scenario.parameters["motor.R_ohm"]
        base = scenario.simulate()
        weaker = scenario.simulate({"motor.R_ohm": 4.0 * nominal})
        # A four times larger winding resistance quarters the stall torque: the servos lag more.
        self.assertGreater(motoflex.rms_deg(weaker), 1.2 * motoflex.rms_deg(base))
        again = scenario.simulate()
        self.assertTrue(np.array_equal(base["measured_rad"], again["measured_rad"]))
        with self.assertRaisesRegex(motoflex.InputError, "motor.R_ohmm"):
            scenario.simulate({"motor.R_ohmm": 1.0})
        with self.assertRaisesRegex(motoflex.InputError, "robot.yaml|no such|not"):
            motoflex.Scenario(os.path.join(SOURCE, "scenarios", "no_such.yaml"))

    def test_sparse_solver_gives_the_exact_solvers_motion(self):
        # solver 'sparse': dWorldStep's LCP solved by motoflex's solver, here inside the module
        # (src/sim/ode_sparse_step.cpp); the same LCP, so the same motion up to rounding (the
        # bundled scenario's encoders are exact; measured 2e-15 rad over its first second).
        step = motoflex.Scenario(NAO, solver="step", duration_s=1.0).simulate()
        sparse = motoflex.Scenario(NAO, solver="sparse", duration_s=1.0).simulate()
        self.assertEqual(sparse["frames_completed"], step["frames_completed"])
        np.testing.assert_allclose(sparse["measured_rad"], step["measured_rad"], rtol=0,
                                   atol=1e-9)
        np.testing.assert_allclose(sparse["torso_position_m"], step["torso_position_m"],
                                   rtol=0, atol=1e-9)
        self.assertGreater(np.ptp(step["measured_rad"], axis=0).max(), 0.05)  # the robot moved
        with self.assertRaisesRegex(motoflex.InputError, "sparse"):
            motoflex.Scenario(NAO, solver="dense")

    def test_torques_and_torso_come_as_arrays(self):
        result = motoflex.simulate(NAO, duration_s=0.2, record_torques=True)
        frames = result["frames_completed"]
        self.assertEqual(result["joint_torque_nm"].shape, (frames, len(result["joint_names"])))
        self.assertEqual(result["torso_position_m"].shape, (frames, 3))
        # Standing: the torso is above the ground and the feet carry the robot's weight.
        self.assertGreater(result["torso_position_m"][-1, 2], 0.2)
        total_force_n = result["foot_force_z_n"][-1].sum()
        self.assertGreater(total_force_n, 40.0)


class LogTest(unittest.TestCase):
    def test_logs_and_parameters_round_trip(self):
        first = sorted(f for f in os.listdir(BENCH_TRAIN) if f.endswith(".csv"))[0]
        log = motoflex.read_log(os.path.join(BENCH_TRAIN, first))
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "copy.csv")
            motoflex.write_log(path, log)
            back = motoflex.read_log(path)
            for key in ("time_s", "commanded_rad", "measured_rad"):
                self.assertTrue(np.array_equal(log[key], back[key]), key)
            self.assertEqual(back["meta"]["robot"], log["meta"]["robot"])
            values = {"motor.R_ohm": 6.5, "gear.A.backlash_rad": 1.0e-5 / 3.0}
            motoflex.write_parameters(os.path.join(tmp, "p.json"), values)
            self.assertEqual(motoflex.read_parameters(os.path.join(tmp, "p.json")), values)


class FitTest(unittest.TestCase):
    def test_fit_and_resume_equal_the_cli(self):
        with tempfile.TemporaryDirectory() as tmp:
            cli_dir = os.path.join(tmp, "cli")
            cli("fit", BENCH_FIT, "--out", cli_dir, "--max-generations", "3", "--threads", "1")
            events = []
            py_dir = os.path.join(tmp, "py")
            summary = motoflex.fit(BENCH_FIT, out=py_dir, max_generations=2, threads=1,
                                   progress=events.append, report=False)
            self.assertEqual([e.generation for e in events if not e.polish], [1, 2])
            self.assertIn("max_generations", summary["stop_reason"])
            self.assertFalse(summary["converged"])
            summary = motoflex.resume(py_dir, max_generations=3, threads=2, report=False)
            # Two sessions (2 + 1 generations, 1 then 2 threads) end where one CLI run of 3 does.
            self.assertEqual(best(py_dir), best(cli_dir))
            self.assertEqual(generations_without_seconds(py_dir),
                             generations_without_seconds(cli_dir))
            self.assertEqual(motoflex.run_summary(py_dir)["best_fitness"], summary["best_fitness"])

    def test_ctrl_c_keeps_the_checkpoint_and_resume_continues(self):
        with tempfile.TemporaryDirectory() as tmp:
            run_dir = os.path.join(tmp, "run")

            def interrupt(progress):
                if progress.generation == 1:
                    raise KeyboardInterrupt

            with self.assertRaises(KeyboardInterrupt):
                motoflex.fit(BENCH_FIT, out=run_dir, max_generations=3, threads=1,
                             progress=interrupt)
            self.assertTrue(os.path.exists(os.path.join(run_dir, "checkpoint.json")))
            self.assertEqual(len(generations_without_seconds(run_dir)), 2)  # header + gen 1
            motoflex.resume(run_dir, report=False)
            cli_dir = os.path.join(tmp, "cli")
            cli("fit", BENCH_FIT, "--out", cli_dir, "--max-generations", "3", "--threads", "1")
            self.assertEqual(best(run_dir), best(cli_dir))

    def test_a_spec_built_in_python_fits_and_is_recorded(self):
        spec = motoflex.FitSpec()
        spec.name = "py_spec"
        spec.scenario_path = BENCH_SCENARIO
        spec.train_data = [BENCH_TRAIN]
        spec.free = [motoflex.FreeParameter("joint.pendulum.friction_nm", lower=0.0, upper=0.3,
                                            start=0.05)]
        spec.strategy.kind = "cma_es"
        spec.strategy.restarts = 0
        spec.budget.max_generations = 2
        spec.seed = 5
        with tempfile.TemporaryDirectory() as tmp:
            spec.out_dir = os.path.join(tmp, "run")
            self.assertEqual(spec.is_valid(), (True, ""))
            summary = motoflex.fit(spec, report=False)
            self.assertTrue(os.path.exists(os.path.join(tmp, "run", "fit.yaml")))
            reread = motoflex.FitSpec.load(os.path.join(tmp, "run", "fit.yaml"))
            self.assertEqual(reread.free[0].pattern, "joint.pendulum.friction_nm")
            self.assertEqual(summary["generations"], 2)
            friction = summary["free"]["joint.pendulum.friction_nm"]
            self.assertTrue(0.0 <= friction <= 0.3)
            self.assertEqual(best(os.path.join(tmp, "run"))[1]["joint.pendulum.friction_nm"],
                             friction)
        bad = motoflex.FitSpec()
        valid, why = bad.is_valid()
        self.assertFalse(valid)
        self.assertIn("scenario", why)


class ExportTest(unittest.TestCase):
    def test_export_writes_what_the_cli_writes(self):
        robot = os.path.join(SOURCE, "scenarios", "robots", "nao")
        with tempfile.TemporaryDirectory() as tmp:
            params = os.path.join(tmp, "p.json")
            motoflex.write_parameters(params, {"motor.R_ohm": 6.5})
            self.assertIn("mjcf", motoflex.export_formats())
            for fmt in ("mjcf", "urdf"):
                py_out = os.path.join(tmp, f"py.{fmt}")
                cli_out = os.path.join(tmp, f"cli.{fmt}")
                info = motoflex.export(params, robot, fmt, py_out)
                cli("export", params, "--robot", robot, "--format", fmt,
                    "--out", cli_out)
                with open(py_out, encoding="utf-8") as a, open(cli_out, encoding="utf-8") as b:
                    # The URDF extension stamps the export time; everything else is identical.
                    stamp = re.compile(r'exported_at="[^"]*"')
                    self.assertEqual(stamp.sub("", a.read()), stamp.sub("", b.read()))
                self.assertTrue(info["read_back_by"])
            with self.assertRaisesRegex(motoflex.InputError, "format"):
                motoflex.export(params, robot, "fbx", os.path.join(tmp, "x"))


class AnalysisTest(unittest.TestCase):
    def test_frequency_response_of_a_delay(self):
        t = np.arange(0.0, 20.0, 0.005)
        rng = np.random.default_rng(1)
        freqs, phases = 0.05 * np.arange(1, 151), rng.uniform(0, 2 * np.pi, 150)

        def command(times):
            return 0.1 * np.sin(2 * np.pi * np.outer(times, freqs) + phases).sum(axis=1)

        delay_s = 0.01
        r = motoflex.frequency_response(t, command(t), command(t - delay_s))
        band = (r["f_hz"] > 0.5) & (r["f_hz"] < 7.0)
        self.assertGreater(band.sum(), 10)
        np.testing.assert_allclose(r["gain_db"][band], 0.0, atol=0.3)
        np.testing.assert_allclose(r["phase_deg"][band], -360.0 * r["f_hz"][band] * delay_s,
                                   atol=3.0)
        same = motoflex.frequency_response(t, command(t), command(t), command(t))
        self.assertGreater(same["coherent_points"], 10)
        self.assertEqual(same["gain_rms_db"], 0.0)
        self.assertIsNone(motoflex.frequency_response(t, np.ones_like(t), command(t)))
        with self.assertRaisesRegex(ValueError, "measured"):
            motoflex.frequency_response(t, command(t), command(t)[:-1])

    def test_parameter_spread_of_two_runs(self):
        with tempfile.TemporaryDirectory() as tmp:
            runs = []
            for name, kp in (("a", 4.0), ("b", 6.0)):
                run = os.path.join(tmp, name)
                os.makedirs(run)
                files = {"run.json": {"kind": "fit"},
                         "inputs.json": {"free": [{"name": "bench.kp", "unit": "1", "lower": 0,
                                                   "upper": 10, "log": False}]},
                         "best.json": {"free": {"bench.kp": kp}},
                         "summary.json": {"best_fitness": 1e-4}}
                for file, content in files.items():
                    with open(os.path.join(run, file), "w", encoding="utf-8") as f:
                        json.dump(content, f)
                runs.append(run)
            spread = motoflex.parameter_spread(runs, k=1.0)
            kp = spread["parameters"][0]
            self.assertEqual(kp["mean"], 5.0)
            self.assertAlmostEqual(kp["lower"], 5.0 - 2.0 ** 0.5)
            with self.assertRaises(motoflex.InputError):
                motoflex.parameter_spread([os.path.join(tmp, "nothing")])


if __name__ == "__main__":
    unittest.main()
