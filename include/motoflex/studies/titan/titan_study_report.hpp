#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "motoflex/studies/titan/titan_paper_study.hpp"
#include "motoflex/studies/titan/titan_study_config.hpp"

namespace motoflex {

// titan.json: every number of the study (units in the key names; a time that never settled is
// null). Layout: {"static": {...}, "updown": {...}, "crawl": {"A": {...}, ...},
// "sim_seconds_per_10s_crawl": ..., "timing": {...}, "paper": {...}}.
nlohmann::ordered_json titan_study_json(const TitanStudyConfig& config,
                                        const TitanPaperStudyResults& results);

// CSV series for the figures: static_knee.csv (Fig. 5), updown.csv, crawl_<P>_<leg>_cycle.csv
// (Fig. 8, 9). Throws std::runtime_error when a file cannot be written.
void write_titan_study_series(const TitanStudyConfig& config, const TitanPaperStudyResults& results,
                              const std::string& out_dir);

// Creates out_dir and writes titan.json, the CSV series, report.md (the numbers beside the
// paper's) and, when `plots`, the PNG figures via scripts/plot_titan.py (a missing python or
// matplotlib only costs the figures, with a warning). Throws std::runtime_error on write errors.
void write_titan_study_report(const TitanStudyConfig& config, const TitanPaperStudyResults& results,
                              const std::string& out_dir, bool plots);

}  // namespace motoflex
