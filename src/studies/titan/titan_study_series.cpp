#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "motoflex/studies/titan/titan_study_report.hpp"

namespace motoflex {
namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

// Writes a CSV with a header and one row per sample of equally long columns.
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& header,
               const std::vector<const std::vector<double>*>& columns) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "w"));
  if (!file) throw std::runtime_error("cannot write " + path.string());
  for (std::size_t c = 0; c < header.size(); ++c) {
    std::fprintf(file.get(), "%s%s", c ? "," : "", header[c].c_str());
  }
  std::fprintf(file.get(), "\n");
  const std::size_t rows = columns.empty() ? 0 : columns.front()->size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      std::fprintf(file.get(), "%s%.9g", c ? "," : "", (*columns[c])[r]);
    }
    std::fprintf(file.get(), "\n");
  }
  if (std::ferror(file.get())) throw std::runtime_error("error writing " + path.string());
}

}  // namespace

void write_titan_study_series(const TitanStudyConfig& config, const TitanPaperStudyResults& results,
                              const std::string& out_dir) {
  const std::filesystem::path dir(out_dir);
  {
    const TitanStaticResult& s = results.stand;
    std::vector<std::string> header = {"time_s"};
    std::vector<const std::vector<double>*> columns = {&s.time_s};
    for (const TitanLeg leg : kTitanLegs) {
      const auto l = static_cast<std::size_t>(leg);
      const std::string name = to_string(leg);
      header.insert(header.end(), {name + "_J3_feedback_nm", name + "_J3_jacobian_nm",
                                   name + "_J4_feedback_nm", name + "_knee_fz_n"});
      columns.insert(columns.end(), {&s.knee_feedback_series_nm[l], &s.knee_jacobian_series_nm[l],
                                     &s.ankle_feedback_series_nm[l], &s.knee_fz_series_n[l]});
    }
    write_csv(dir / "static_knee.csv", header, columns);
  }
  {
    const TitanUpDownResult& u = results.updown;
    write_csv(
        dir / "updown.csv",
        {"time_s", "body_height_m", "potential_j", "work_feedback_j", "work_jacobian_j"},
        {&u.time_s, &u.body_height_m, &u.potential_j, &u.work_feedback_j, &u.work_jacobian_j});
  }
  const std::string leg = to_string(config.plan.crawl.plot_leg);
  for (const TitanCrawlResult& c : results.crawls) {
    write_csv(
        dir / ("crawl_" + std::string(to_string(c.posture)) + "_" + leg + "_cycle.csv"),
        {"cycle_time_s", "J1_torque_nm", "J2_torque_nm", "J3_torque_nm", "J1_power_w", "J2_power_w",
         "J3_power_w", "J1_feedback_torque_nm", "J2_feedback_torque_nm", "J3_feedback_torque_nm",
         "J1_feedback_power_w", "J2_feedback_power_w", "J3_feedback_power_w"},
        {&c.cycle_time_s, &c.cycle_torque_nm[0], &c.cycle_torque_nm[1], &c.cycle_torque_nm[2],
         &c.cycle_power_w[0], &c.cycle_power_w[1], &c.cycle_power_w[2],
         &c.cycle_feedback_torque_nm[0], &c.cycle_feedback_torque_nm[1],
         &c.cycle_feedback_torque_nm[2], &c.cycle_feedback_power_w[0], &c.cycle_feedback_power_w[1],
         &c.cycle_feedback_power_w[2]});
  }
}

}  // namespace motoflex
