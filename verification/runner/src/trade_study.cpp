// The machinery of a speed/accuracy study (trade_study.hpp): the runs, the tables, the
// cheapest settings and the plots; what a run's error is belongs to the problem.
#include "trade_study.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/stop_request.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/solver/solve.hpp"
#include "lituya/sweep/scene_edit.hpp"
#include "lituya/verify/speed_accuracy.hpp"

namespace lituya::verify {

namespace fs = std::filesystem;

namespace {

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

// The knobs a run changed from the base, e.g. "courant = 0.7, bulk_modulus = 2.15e5".
std::string describe(const TradeStudy& study, const StudyRun& r) {
  std::string out;
  for (std::size_t k = 0; k < study.keys.size(); ++k)
    if (r.setting[k] != study.base[k])
      out += (out.empty() ? "" : ", ") + study.names[k] + " = " + r.setting[k];
  return out.empty() ? "base (" + setting_name(study, study.base) + ")" : out;
}

bool counts(const TradeStudy& study, const StudyRun& r) {
  return std::abs(r.volume_change) <= study.max_volume_change;
}

// The runs as the selection sees them for error `e`; `volume_rule` false: every run counts.
std::vector<TradeRun> trade_runs(const TradeStudy& study, const std::vector<StudyRun>& runs,
                                 std::size_t e, bool volume_rule = true) {
  std::vector<TradeRun> out;
  for (const StudyRun& r : runs)
    out.push_back({r.knob, r.value, r.errors.at(e), r.wall_time, !volume_rule || counts(study, r)});
  return out;
}

// Error e against wall time, log-log, one curve per knob (the knob_<name>.csv files), each
// point labelled by its value, the bounds as dashed lines.
void plot_error_against_time(const TradeStudy& study, const CaseContext& context,
                             const std::vector<StudyRun>& runs, std::size_t e, CaseResult& result) {
  const StudyError& error = study.errors[e];
  double y_low = 0.9 * study.bounds.front(), y_high = 1.1 * study.bounds.back();
  for (const StudyRun& r : runs)
    if (std::isfinite(r.errors[e]) && r.errors[e] > 0) {
      y_low = std::min(y_low, 0.9 * r.errors[e]);
      y_high = std::max(y_high, 1.1 * r.errors[e]);
    }
  std::ostringstream gp;
  gp << "# Written by `lituya verify --case " << fs::path(context.source).filename().string()
     << "`; re-run here: gnuplot " << error.plot << ".gp\n"
     << "set terminal pngcairo size 1000,650 noenhanced\nset output '" << error.plot
     << ".png'\nset datafile separator ','\nset logscale xy\nset grid\nset key below\n"
     << "set title "
     << post::gnuplot_text(error.title + "\none knob changed at a time from " +
                           setting_name(study, study.base))
     << "\nset xlabel 'wall time of the solve, one thread (s)'\n"
     << "set ylabel " << post::gnuplot_text(error.label)
     << "\n"
     // The data and both bounds in view, without the empty decade a log autoscale adds.
     << "set yrange [" << y_low << ":" << y_high << "]\n"
     << "set ytics (0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.03, 0.04, 0.05, "
        "0.06, 0.07, 0.08, 0.1, "
        "0.12, 0.15, 0.2, 0.3, 0.5, 1)\n";
  for (double bound : study.bounds)
    gp << "set arrow from graph 0, first " << bound << " to graph 1, first " << bound
       << " nohead dt 2 lc rgb 'gray40'\n";
  gp << "plot \\\n";
  std::vector<std::pair<std::string, std::string>> curves;
  for (const StudyKnob& k : study.knobs) curves.emplace_back(k.name, k.label);
  if (study.combined) curves.emplace_back("combined", "combined (each knob at its cheapest)");
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const bool knob = curves[c].first != "combined";
    const std::string csv = "knob_" + curves[c].first + ".csv";
    // The knobs in gnuplot's colours, the combined runs in black.
    const std::string colour = knob ? "lt " + std::to_string(c + 1) : "rgb 'black'";
    const std::string column = std::to_string(3 + e);
    gp << "  '" << csv << "' skip 1 using 2:" << column << " with linespoints lw 2 pt 7 "
       << (knob ? "" : "lc ") << colour << " title " << post::gnuplot_text(curves[c].second)
       << ", \\\n";
    // Each point labelled by its value (a combined run by the error bound it was chosen for).
    gp << "  '" << csv << "' skip 1 using 2:" << column << ":(sprintf('" << (knob ? "" : "<= ")
       << "%.3g', $1)) with labels offset 0,0.8 tc " << colour << " font ',8' notitle"
       << (c + 1 < curves.size() ? ", \\\n" : "\n");
  }
  const fs::path png = context.work / (error.plot + ".png");
  if (post::run_gnuplot_script(png, gp.str()))
    result.plots.push_back(fs::relative(png, context.report));
}

}  // namespace

const std::vector<std::string>& trade_knob_keys() {
  static const std::vector<std::string> keys = {"mesh.cell_size", "mesh.points_per_cell",
                                                "stage.release.courant",
                                                "material.water.bulk_modulus"};
  return keys;
}

const std::vector<std::string>& trade_knob_names() {
  static const std::vector<std::string> names = {"cell_size", "points_per_cell", "courant",
                                                 "bulk_modulus"};
  return names;
}

std::string setting_name(const TradeStudy& study, const std::vector<std::string>& setting) {
  std::string name;
  for (std::size_t k = 0; k < study.names.size(); ++k)
    name += (k ? "_" : "") + study.names[k] + "=" + setting[k];
  return name;
}

StudyRun run_study_setting(const TradeStudy& study, const std::vector<std::string>& setting,
                           const fs::path& folder, int threads) {
  StudyRun r;
  r.setting = setting;
  r.measured.assign(study.measure_columns.size(), std::numeric_limits<double>::quiet_NaN());
  r.errors.assign(study.errors.size(), std::numeric_limits<double>::quiet_NaN());
  r.wall_time = r.volume_change = std::numeric_limits<double>::quiet_NaN();
  fs::create_directories(folder);
  const sweep::SceneText scene(study.scene);
  std::vector<sweep::KeySetting> settings;
  for (std::size_t k = 0; k < study.keys.size(); ++k) {
    const sweep::KeyTarget target = scene.locate(study.keys[k]);
    settings.push_back({target, scene.literals(target, {setting[k]}).front()});
  }
  write_file_atomically(
      folder / "scene.toml",
      scene.with_values(settings, {study.name + " study: " + setting_name(study, setting)}));
  try {
    r.points =
        pre::preprocess(folder / "scene.toml", folder / "case", /*overwrite=*/true).liquid_points;
    const solver::SolveOptions options = report_solve_options(threads);
    for (int k = 0; k < study.repeats; ++k) {
      double wall = 0;
      r.steps = r.release_steps = 0;
      for (const solver::StageReport& s : solver::solve_case(folder / "case", options)) {
        wall += s.wall_time;
        r.steps += s.steps;
        if (s.stage == "release") r.release_steps += s.steps;
      }
      r.wall_times.push_back(wall);
      if (wall >= study.repeat_below) break;
    }
    r.wall_time = median(r.wall_times);
    const auto frames = read_series(folder / "case", "release", "liquid");
    auto total_volume = [](const fs::path& vtu) {
      int components = 0;
      double sum = 0;
      for (double v : read_point_array(vtu, "volume", components)) sum += v;
      return sum;
    };
    r.volume_change = total_volume(frames.back().file) / total_volume(frames.front().file) - 1;
    study.measure(folder / "case", r);
  } catch (const RunStopped&) {
    throw;  // Ctrl-C stops the study, not only this run
  } catch (const std::exception& e) {
    // A run that goes unstable (or cannot run) is a result of the study: no error, no time.
    r.failure = e.what();
    r.wall_time = std::numeric_limits<double>::quiet_NaN();
    std::fill(r.errors.begin(), r.errors.end(), std::numeric_limits<double>::quiet_NaN());
  }
  return r;
}

std::vector<StudyRun> run_trade_study(const TradeStudy& study, const CaseContext& context,
                                      CaseResult& result) {
  // Every setting once: a setting shared by several knobs (the base) is run once, on one thread
  // (the cost is one core's).
  std::map<std::vector<std::string>, StudyRun> done;
  auto run = [&](const std::vector<std::string>& setting) -> const StudyRun& {
    auto it = done.find(setting);
    if (it == done.end()) {
      std::cout << study.name << ": " << setting_name(study, setting) << std::flush;
      StudyRun r = run_study_setting(study, setting,
                                     context.work / "runs" / setting_name(study, setting), 1);
      std::cout << ": ";
      if (r.failure.empty()) {
        for (std::size_t e = 0; e < study.errors.size(); ++e)
          std::cout << study.errors[e].name << " " << fixed(r.errors[e], 4) << ", ";
        std::cout << fixed(r.wall_time, 2) << " s" << std::endl;
      } else {
        std::cout << "failed: " << r.failure << std::endl;
      }
      it = done.emplace(setting, std::move(r)).first;
    }
    return it->second;
  };

  std::vector<StudyRun> runs;  // one row per knob and value (the base once per knob)
  for (const StudyKnob& knob : study.knobs) {
    const std::size_t key =
        std::find(study.keys.begin(), study.keys.end(), knob.key) - study.keys.begin();
    for (const std::string& value : knob.values) {
      std::vector<std::string> setting = study.base;
      setting.at(key) = value;
      StudyRun r = run(setting);
      r.knob = knob.name;
      r.value = std::stod(value);
      runs.push_back(std::move(r));
    }
  }
  // The combined setting: every knob at its own cheapest value within the bound for the first
  // error (the base value where none is), run to see whether the savings add up.
  if (study.combined)
    for (double bound : study.bounds) {
      const std::vector<TradeRun> trade = trade_runs(study, runs, 0);
      std::vector<std::string> setting = study.base;
      for (std::size_t k = 0; k < study.names.size(); ++k)
        if (const auto i = cheapest_within(trade, bound, study.names[k]))
          setting[k] = runs[*i].setting[k];
      StudyRun r = run(setting);
      r.knob = "combined";
      r.value = bound;
      const bool listed = std::any_of(runs.begin(), runs.end(), [&](const StudyRun& q) {
        return q.knob == "combined" && q.setting == setting;
      });
      if (!listed) runs.push_back(std::move(r));
    }

  // The table of every run, and the CSV of every run.
  std::vector<std::vector<double>> rows;
  std::ostringstream table;
  table << "| knob | setting | liquid points | steps | wall time (s) |";
  for (const std::string& m : study.measure_columns) table << " " << m << " |";
  for (const StudyError& e : study.errors) table << " " << e.label << " |";
  table << " water volume change | failure |\n|---|---|---|---|---|";
  for (std::size_t k = 0; k < study.measure_columns.size() + study.errors.size(); ++k)
    table << "---|";
  table << "---|---|\n";
  for (const StudyRun& r : runs) {
    std::vector<double> row;
    for (const std::string& v : r.setting) row.push_back(std::stod(v));
    row.insert(row.end(), {static_cast<double>(r.points), static_cast<double>(r.steps),
                           static_cast<double>(r.release_steps), r.wall_time});
    row.insert(row.end(), r.measured.begin(), r.measured.end());
    row.insert(row.end(), r.errors.begin(), r.errors.end());
    row.push_back(r.volume_change);
    rows.push_back(row);
    table << "| " << r.knob << " | " << describe(study, r) << " | " << r.points << " | " << r.steps
          << " | " << fixed(r.wall_time, 2) << " |";
    for (double m : r.measured) table << " " << fixed(m, 5) << " |";
    for (double e : r.errors) table << " " << fixed(e, 4) << " |";
    table << " " << fixed(100 * r.volume_change, 2) << " %"
          << (counts(study, r) ? "" : " (excluded)") << " | " << r.failure << " |\n";
  }
  std::string header;
  for (const std::string& n : study.names) header += n + ",";
  header += "liquid_points,steps,release_steps,wall_time";
  for (const std::string& m : study.measure_columns) header += "," + m;
  for (const StudyError& e : study.errors) header += "," + e.name;
  header += ",volume_change";
  write_csv(context.work / (study.name + ".csv"), header, rows);

  // One CSV per knob for the plots (sorted by the knob's value): value, wall time, errors.
  std::vector<std::string> curves;
  for (const StudyKnob& k : study.knobs) curves.push_back(k.name);
  if (study.combined) curves.push_back("combined");
  std::string knob_header = "value,wall_time";
  for (const StudyError& e : study.errors) knob_header += "," + e.name;
  for (const std::string& curve : curves) {
    std::vector<std::vector<double>> knob_rows;
    for (const StudyRun& r : runs)
      if (r.knob == curve) {
        knob_rows.push_back({r.value, r.wall_time});
        knob_rows.back().insert(knob_rows.back().end(), r.errors.begin(), r.errors.end());
      }
    std::sort(knob_rows.begin(), knob_rows.end());
    write_csv(context.work / ("knob_" + curve + ".csv"), knob_header, knob_rows);
  }

  // The cheapest runs within each bound, per error: of all runs, without the volume rule, and
  // per knob.
  std::ostringstream cheapest;
  cheapest << "| error | at most | knob | cheapest setting | wall time (s) | error |\n"
              "|---|---|---|---|---|---|\n";
  std::vector<std::string> groups = {"", "volume rule ignored"};
  groups.insert(groups.end(), curves.begin(), curves.end());
  std::ostringstream best_errors;
  for (std::size_t e = 0; e < study.errors.size(); ++e) {
    const std::vector<TradeRun> trade = trade_runs(study, runs, e);
    const std::vector<TradeRun> unfiltered = trade_runs(study, runs, e, /*volume_rule=*/false);
    for (double bound : study.bounds)
      for (const std::string& group : groups) {
        const bool raw = group == "volume rule ignored";
        const auto i =
            raw ? cheapest_within(unfiltered, bound) : cheapest_within(trade, bound, group);
        cheapest << "| " << study.errors[e].label << " | " << fixed(bound, 2) << " | "
                 << (group.empty() ? "any"
                     : raw         ? "any, volume rule ignored"
                                   : group)
                 << " | " << (i ? describe(study, runs[*i]) : "none") << " | "
                 << (i ? fixed(runs[*i].wall_time, 2) : "-") << " | "
                 << (i ? fixed(trade[*i].error, 4) : "-") << " |\n";
      }
    double best = std::numeric_limits<double>::infinity();
    for (const TradeRun& t : trade)
      if (std::isfinite(t.error) && t.admissible) best = std::min(best, t.error);
    best_errors << "Smallest " << study.errors[e].label
                << " of the runs that count: " << fixed(best, 4) << ".\n";
  }
  write_file_atomically(context.work / (study.name + ".md"), [&](std::ostream& md) {
    md << "# " << study.problem << " vs wall time (" << (context.full ? "full" : "quick")
       << " study)\n\nBase: " << setting_name(study, study.base)
       << "; one thread; wall time of the solve, median of up to " << study.repeats
       << " repeats of solves under " << study.repeat_below
       << " s.\nA run counts only if its water volume changed by at most "
       << fixed(100 * study.max_volume_change, 0) << " %.\n"
       << best_errors.str() << "\n"
       << study.notes << "\n"
       << table.str() << "\n"
       << cheapest.str();
  });
  std::cout << study.name << ": cheapest settings (base " << setting_name(study, study.base)
            << ")\n"
            << cheapest.str() << std::flush;
  for (std::size_t e = 0; e < study.errors.size(); ++e)
    plot_error_against_time(study, context, runs, e, result);
  return runs;
}

std::pair<std::vector<double>, std::vector<double>> knob_cost(const std::vector<StudyRun>& runs,
                                                              const std::string& knob, double lo,
                                                              double hi, bool steps) {
  std::vector<double> x, y;
  for (const StudyRun& r : runs)
    if (r.knob == knob && r.value >= lo && r.value <= hi) {
      x.push_back(r.value);
      y.push_back(steps ? static_cast<double>(r.release_steps) : r.wall_time);
    }
  return {x, y};
}

double error_spread(const std::vector<StudyRun>& runs, const std::string& knob, std::size_t e) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const StudyRun& r : runs)
    if (r.knob == knob) {
      if (!std::isfinite(r.errors.at(e))) return std::numeric_limits<double>::quiet_NaN();
      lo = std::min(lo, r.errors[e]);
      hi = std::max(hi, r.errors[e]);
    }
  return hi - lo;
}

}  // namespace lituya::verify
