#include "motoflex/studies/seed001/seed001_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/build_info.hpp"
#include "motoflex/io/plot_script.hpp"

namespace motoflex {
namespace {

nlohmann::ordered_json number(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json();
}

std::string series_name(const Seed001Run& run) {
  return "series/" + run.walk + "__" + run.variant + ".csv";
}

std::string zmp_series_name(const std::string& variant, std::size_t index) {
  return "series/zmp__" + variant + "__" + std::to_string(index) + ".csv";
}

double median(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }),
               values.end());
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The replicas one by one and their medians (a fall time's median over the replicas that fell).
nlohmann::ordered_json ensemble_json(const std::vector<Seed001Replica>& replicas) {
  nlohmann::ordered_json j;
  std::vector<double> fall_s, speed, mean_speed, lateral;
  int fell = 0;
  for (const Seed001Replica& r : replicas) {
    fell += r.fell ? 1 : 0;
    fall_s.push_back(r.fall_s);
    speed.push_back(r.speed_mm_s);
    mean_speed.push_back(r.mean_speed_mm_s);
    lateral.push_back(r.lateral_m);
  }
  const auto list = [](const std::vector<double>& values) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const double v : values) out.push_back(number(v));
    return out;
  };
  j["size"] = replicas.size();
  j["fell"] = fell;
  j["fall_s_median"] = number(median(fall_s));
  j["speed_mm_s_median"] = number(median(speed));
  j["mean_speed_mm_s_median"] = number(median(mean_speed));
  j["lateral_m_median"] = number(median(lateral));
  j["fall_s"] = list(fall_s);
  j["speed_mm_s"] = list(speed);
  j["mean_speed_mm_s"] = list(mean_speed);
  j["lateral_m"] = list(lateral);
  return j;
}

nlohmann::ordered_json run_json(const Seed001Run& run, const std::string& series) {
  nlohmann::ordered_json j;
  if (!run.pending.empty()) {
    j["pending"] = run.pending;
    return j;
  }
  if (!run.unplannable.empty()) {
    j["unplannable"] = run.unplannable;
    return j;
  }
  j["speed_mm_s"] = number(run.speed_mm_s);
  j["fell"] = run.fell;
  j["fall_s"] = number(run.fall_s);
  j["fall_direction"] = run.fall_direction ? nlohmann::ordered_json(to_string(*run.fall_direction))
                                           : nlohmann::ordered_json();
  j["pitch_alternation"] = number(run.pitch_alternation);
  j["pitch_range_rad"] = number(run.pitch_range_rad);
  j["mean_speed_mm_s"] = number(run.mean_speed_mm_s);
  j["distance_m"] = run.distance_m;
  j["lateral_m"] = run.lateral_m;
  j["max_abs_roll_rad"] = run.max_abs_roll_rad;
  j["fall_tilt_rad"] = {{"roll", number(run.fall_roll_rad)}, {"pitch", number(run.fall_pitch_rad)}};
  j["steady_s"] = {run.steady_start_s, run.steady_end_s};
  j["step_s"] = run.step_s;
  j["end"] = to_string(run.end);
  j["end_time_s"] = run.end_time_s;
  j["end_detail"] = run.end_detail;
  j["series"] = series;
  if (!run.ensemble.empty()) j["ensemble"] = ensemble_json(run.ensemble);
  if (!run.seed_ensemble.empty()) j["quickstep_seed_ensemble"] = ensemble_json(run.seed_ensemble);
  return j;
}

std::string series_csv(const RolloutResult& r) {
  std::string text = "time_s,torso_x_m,torso_y_m,torso_z_m,roll_rad,pitch_rad\n";
  char line[256];
  for (std::size_t f = 0; f < r.time_s.size(); ++f) {
    std::snprintf(line, sizeof line, "%.6g,%.9g,%.9g,%.9g,%.9g,%.9g\n", r.time_s[f],
                  r.torso_position_m[3 * f], r.torso_position_m[3 * f + 1],
                  r.torso_position_m[3 * f + 2], r.imu_roll_rad[f], r.imu_pitch_rad[f]);
    text += line;
  }
  return text;
}

// A bundled file relative to motoflex's data directory, so that the JSON does not depend on
// where the checkout lives; any other path as given.
std::string shown_path(const std::string& path) {
  const std::string data = std::filesystem::path(data_directory()).lexically_normal().string();
  const std::string normal = std::filesystem::path(path).lexically_normal().string();
  if (!data.empty() && normal.rfind(data + "/", 0) == 0) return normal.substr(data.size() + 1);
  return path;
}

}  // namespace

nlohmann::ordered_json seed001_json(const Seed001Config& config, const Seed001Results& results) {
  nlohmann::ordered_json j;
  for (const Seed001Run& run : results.runs) {
    j[run.walk][run.variant] = run_json(run, run.pending.empty() ? series_name(run) : "");
  }
  if (results.zmp) {
    const Seed001ZmpResult& zmp = *results.zmp;
    nlohmann::ordered_json z;
    z["walk"] = zmp.walk;
    for (const Seed001ZmpSetting& d : zmp.defaults) z["defaults"][d.option] = number(d.value);
    z["rule"] =
        "chosen: the trial that walks to the end without falling with the smallest peak "
        "|torso roll|";
    for (std::size_t v = 0; v < zmp.variants.size(); ++v) {
      nlohmann::ordered_json variant;
      const int chosen = zmp.chosen[v];
      variant["chosen"] = nlohmann::ordered_json();
      if (chosen >= 0) {
        const Seed001ZmpSetting& setting = zmp.trials[v][static_cast<std::size_t>(chosen)].setting;
        variant["chosen"] = {{"option", setting.option}, {"value", setting.value}};
      }
      variant["trials"] = nlohmann::ordered_json::array();
      for (std::size_t k = 0; k < zmp.trials[v].size(); ++k) {
        const Seed001ZmpTrial& trial = zmp.trials[v][k];
        nlohmann::ordered_json row;
        row["option"] = trial.setting.option;
        row["value"] = trial.setting.value;
        const nlohmann::ordered_json run = run_json(trial.run, zmp_series_name(zmp.variants[v], k));
        for (const auto& [key, value] : run.items()) row[key] = value;
        variant["trials"].push_back(row);
      }
      z["variants"][zmp.variants[v]] = variant;
    }
    j["zmp_experiment"] = z;
  }
  for (const Seed001Walk& walk : config.walks) {
    if (walk.figure.empty()) continue;
    j["figures"][walk.name] = {
        {"signal", walk.figure},
        {"png", (walk.figure == "pitch" ? "fig3_pitch_" : "fig4_roll_") + walk.name + ".png"}};
  }
  if (results.zmp) j["figures"]["zmp_experiment"] = {{"png", "zmp_" + results.zmp->walk + ".png"}};
  j["meta"] = {{"config", shown_path(config.path)}, {"motoflex", version()}};
  return j;
}

void write_seed001_report(const Seed001Config& config, const Seed001Results& results,
                          const std::string& out_dir, bool plots) {
  const std::filesystem::path dir(out_dir);
  std::filesystem::create_directories(dir / "series");
  for (const Seed001Run& run : results.runs) {
    if (!run.pending.empty()) continue;
    write_file_atomically((dir / series_name(run)).string(), series_csv(run.result));
  }
  if (results.zmp) {
    for (std::size_t v = 0; v < results.zmp->variants.size(); ++v) {
      for (std::size_t k = 0; k < results.zmp->trials[v].size(); ++k) {
        const Seed001Run& run = results.zmp->trials[v][k].run;
        if (!run.unplannable.empty()) continue;
        write_file_atomically((dir / zmp_series_name(results.zmp->variants[v], k)).string(),
                              series_csv(run.result));
      }
    }
  }
  const std::string json_path = (dir / "seed001.json").string();
  write_file_atomically(json_path, seed001_json(config, results).dump(2) + "\n");
  if (plots) run_plot_script("plot_seed001.py", {out_dir});
}

}  // namespace motoflex
