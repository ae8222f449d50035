// The speed/accuracy trade of the dam break (verification/speed_accuracy/README.md): the dam
// break of verification/dam_break run with one knob at a time changed from its quick setting,
// each run's RMS depth error against Ritter's solution (the dam_break case's own measure)
// against the wall time of its solve on one thread, and the cheapest runs within 5 % and 10 %.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

#include "case_support.hpp"
#include "dam_break_measure.hpp"
#include "lituya/common/atomic_file.hpp"
#include "lituya/common/stop_request.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/solver/solve.hpp"
#include "lituya/sweep/scene_edit.hpp"
#include "lituya/verify/speed_accuracy.hpp"

namespace lituya::verify {

namespace {

namespace fs = std::filesystem;

// A knob: the scene key, its name in tables and file names, a label for the plot, its values.
struct Knob {
  std::string key, name, label;
  std::vector<std::string> values;
};

// The four knobs of the study, as `lituya sweep` names them, in the order of the base setting.
const std::vector<std::string> kKeys = {"mesh.cell_size", "mesh.points_per_cell",
                                        "stage.release.courant", "material.water.bulk_modulus"};
const std::vector<std::string> kNames = {"cell_size", "points_per_cell", "courant", "bulk_modulus"};

struct RunRecord {
  std::string knob;  // the knob changed from the base, or "combined"
  double value = 0;  // the knob's value; for "combined", the error threshold it was chosen for
  std::vector<std::string> setting;  // the value of each of kKeys
  std::size_t points = 0;            // liquid points
  long steps = 0;
  std::vector<double> wall_times;  // s, of each repeat of the solve
  double wall_time = NAN;          // s, their median
  DamBreakMeasure measure;
  double volume_change = NAN;  // total water volume at the last frame over the first, minus 1
  std::string failure;         // why the run gave no measure (e.g. it went unstable)
};

std::string setting_name(const std::vector<std::string>& setting) {
  std::string name;
  for (std::size_t k = 0; k < kNames.size(); ++k)
    name += (k ? "_" : "") + kNames[k] + "=" + setting[k];
  return name;
}

// pre + solve of the base scene with `setting`, in <work>/runs/<setting>/; the solve is timed
// on one thread and repeated while it takes less than `repeat_below` s, up to `repeats` times.
RunRecord run_setting(const sweep::SceneText& scene, const std::vector<std::string>& setting,
                      const fs::path& work, int repeats, double repeat_below) {
  RunRecord r;
  r.setting = setting;
  const fs::path folder = work / "runs" / setting_name(setting);
  fs::create_directories(folder);
  std::vector<sweep::KeySetting> settings;
  for (std::size_t k = 0; k < kKeys.size(); ++k) {
    const sweep::KeyTarget target = scene.locate(kKeys[k]);
    settings.push_back({target, scene.literals(target, {setting[k]}).front()});
  }
  write_file_atomically(
      folder / "scene.toml",
      scene.with_values(settings, {"speed/accuracy study: " + setting_name(setting)}));
  try {
    r.points =
        pre::preprocess(folder / "scene.toml", folder / "case", /*overwrite=*/true).liquid_points;
    const solver::SolveOptions options = report_solve_options(1);
    for (int k = 0; k < repeats; ++k) {
      double wall = 0;
      long steps = 0;
      for (const solver::StageReport& s : solver::solve_case(folder / "case", options)) {
        wall += s.wall_time;
        steps += s.steps;
      }
      r.wall_times.push_back(wall);
      r.steps = steps;
      if (wall >= repeat_below) break;
    }
    r.wall_time = median(r.wall_times);
    r.measure = measure_dam_break(folder / "case");
    const auto frames = read_series(folder / "case", "release", "liquid");
    auto total_volume = [](const fs::path& vtu) {
      int components = 0;
      double sum = 0;
      for (double v : read_point_array(vtu, "volume", components)) sum += v;
      return sum;
    };
    r.volume_change = total_volume(frames.back().file) / total_volume(frames.front().file) - 1;
  } catch (const RunStopped&) {
    throw;  // Ctrl-C stops the study, not only this run
  } catch (const std::exception& e) {
    // A run that goes unstable (or cannot run) is a result of the study: no error, no time.
    r.failure = e.what();
    r.measure.rms_error = std::numeric_limits<double>::quiet_NaN();
  }
  return r;
}

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::string describe(const RunRecord& r, const std::vector<std::string>& base) {
  std::string out;
  for (std::size_t k = 0; k < kKeys.size(); ++k)
    if (r.setting[k] != base[k])
      out += (out.empty() ? "" : ", ") + kNames[k] + " = " + r.setting[k];
  return out.empty() ? "base (" + setting_name(base) + ")" : out;
}

}  // namespace

void run_speed_accuracy(const CaseContext& context, CaseResult& result) {
  const DamBreakSetup setup;
  const sweep::SceneText scene(context.source.parent_path() / "dam_break" / "scene_quick.toml");
  // The base setting: the dam_break quick scene's (h = 0.02 m, 4 points per cell, Courant 0.5,
  // K_w = 2.15e7 Pa); the quick variant starts from 0.04 m cells to stay within seconds.
  std::vector<std::string> base = {"0.02", "4", "0.5", "2.15e7"};
  std::vector<Knob> knobs;
  if (context.full) {
    knobs = {{kKeys[0],
              kNames[0],
              "cell size h (m)",
              {"0.04", "0.03", "0.02", "0.014", "0.01", "0.005"}},
             {kKeys[1], kNames[1], "points per cell", {"1", "3", "4", "9", "16"}},
             {kKeys[2], kNames[2], "Courant number", {"0.1", "0.2", "0.3", "0.5", "0.7", "0.9"}},
             {kKeys[3],
              kNames[3],
              "water bulk modulus (Pa)",
              {"2.15e4", "2.15e5", "2.15e6", "2.15e7", "2.15e8", "2.15e9"}}};
  } else {
    base[0] = "0.04";
    knobs = {{kKeys[2], kNames[2], "Courant number", {"0.25", "0.5"}}};
  }
  const int repeats = context.full ? 3 : 1;
  const double repeat_below = 10.0;  // s: shorter solves are repeated and the median taken

  // Every run once: a setting shared by several knobs (the base) is run once.
  std::map<std::vector<std::string>, RunRecord> done;
  auto run = [&](const std::vector<std::string>& setting) -> const RunRecord& {
    auto it = done.find(setting);
    if (it == done.end()) {
      std::cout << "speed_accuracy: " << setting_name(setting) << std::flush;
      RunRecord r = run_setting(scene, setting, context.work, repeats, repeat_below);
      std::cout << ": "
                << (r.failure.empty() ? "error/H " + fixed(r.measure.rms_error / setup.h0, 4) +
                                            ", " + fixed(r.wall_time, 2) + " s"
                                      : "failed: " + r.failure)
                << std::endl;
      it = done.emplace(setting, std::move(r)).first;
    }
    return it->second;
  };

  std::vector<RunRecord> runs;  // one row per knob and value (the base once per knob)
  for (std::size_t k = 0; k < knobs.size(); ++k) {
    const std::size_t key = std::find(kKeys.begin(), kKeys.end(), knobs[k].key) - kKeys.begin();
    for (const std::string& value : knobs[k].values) {
      std::vector<std::string> setting = base;
      setting[key] = value;
      RunRecord r = run(setting);
      r.knob = knobs[k].name;
      r.value = std::stod(value);
      runs.push_back(std::move(r));
    }
  }
  // A run counts only if its water kept its volume to 1 % (the error against Ritter cannot see
  // a compressible water; README.md).
  const double max_volume_change = 0.01;
  auto trade_runs = [&] {
    std::vector<TradeRun> out;
    for (const RunRecord& r : runs)
      out.push_back({r.knob, r.value, r.measure.rms_error / setup.h0, r.wall_time,
                     std::abs(r.volume_change) <= max_volume_change});
    return out;
  };
  const std::vector<double> thresholds = {0.05, 0.10};
  // The combined setting: every knob at its own cheapest value within the threshold (the base
  // value where none is), run to see whether the savings add up.
  if (context.full)
    for (double threshold : thresholds) {
      const std::vector<TradeRun> trade = trade_runs();
      std::vector<std::string> setting = base;
      for (std::size_t k = 0; k < kNames.size(); ++k)
        if (const auto i = cheapest_within(trade, threshold, kNames[k]))
          setting[k] = runs[*i].setting[k];
      RunRecord r = run(setting);
      r.knob = "combined";
      r.value = threshold;
      const bool listed = std::any_of(runs.begin(), runs.end(), [&](const RunRecord& q) {
        return q.knob == "combined" && q.setting == setting;
      });
      if (!listed) runs.push_back(std::move(r));
    }
  const std::vector<TradeRun> trade = trade_runs();

  // The table of every run, and one CSV per knob for the plot (sorted by the knob's value).
  std::vector<std::vector<double>> rows;
  std::ostringstream table;
  table << "| knob | setting | liquid points | steps | wall time (s) | RMS depth error (m) | "
           "error / H | water volume change | depth at the dam (m) | h = 0.1 H at (x - x_dam) / "
           "(c0 t) |\n"
           "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const RunRecord& r : runs) {
    std::vector<double> row;
    for (const std::string& v : r.setting) row.push_back(std::stod(v));
    row.insert(row.end(), {static_cast<double>(r.points), static_cast<double>(r.steps), r.wall_time,
                           r.measure.rms_error, r.measure.rms_error / setup.h0, r.volume_change,
                           r.failure.empty() ? r.measure.depth_at_dam : NAN,
                           r.failure.empty() ? r.measure.tenth_position : NAN});
    rows.push_back(row);
    table << "| " << r.knob << " | " << describe(r, base) << " | " << r.points << " | " << r.steps
          << " | " << fixed(r.wall_time, 2) << " | " << fixed(r.measure.rms_error, 5) << " | "
          << fixed(r.measure.rms_error / setup.h0, 4) << " | " << fixed(100 * r.volume_change, 2)
          << " %" << (std::abs(r.volume_change) <= max_volume_change ? "" : " (excluded)") << " | "
          << (r.failure.empty() ? fixed(r.measure.depth_at_dam, 4) : "failed: " + r.failure)
          << " | " << (r.failure.empty() ? fixed(r.measure.tenth_position, 3) : "-") << " |\n";
  }
  const std::string header =
      "cell_size,points_per_cell,courant,bulk_modulus,liquid_points,steps,wall_time,"
      "rms_error,error_over_h,volume_change,depth_at_dam,tenth_position";
  write_csv(context.work / "speed_accuracy.csv", header, rows);

  // The cheapest runs within each threshold: of all runs, and per knob.
  std::ostringstream cheapest;
  cheapest << "| error / H at most | knob | cheapest setting | wall time (s) | error / H |\n"
              "|---|---|---|---|---|\n";
  std::vector<TradeRun> unfiltered = trade;  // the same runs without the volume rule
  for (TradeRun& t : unfiltered) t.admissible = true;
  std::vector<std::string> groups = {"", "volume rule ignored"};
  for (const Knob& k : knobs) groups.push_back(k.name);
  if (context.full) groups.push_back("combined");
  for (double threshold : thresholds)
    for (const std::string& group : groups) {
      const bool raw = group == "volume rule ignored";
      const auto i =
          raw ? cheapest_within(unfiltered, threshold) : cheapest_within(trade, threshold, group);
      cheapest << "| " << fixed(threshold, 2) << " | "
               << (group.empty() ? "any"
                   : raw         ? "any, volume rule ignored"
                                 : group)
               << " | " << (i ? describe(runs[*i], base) : "none") << " | "
               << (i ? fixed(runs[*i].wall_time, 2) : "-") << " | "
               << (i ? fixed(trade[*i].error, 4) : "-") << " |\n";
    }
  double best = std::numeric_limits<double>::infinity();
  for (const TradeRun& t : trade)
    if (std::isfinite(t.error) && t.admissible) best = std::min(best, t.error);
  write_file_atomically(context.work / "speed_accuracy.md", [&](std::ostream& md) {
    md << "# Dam break: error against Ritter vs wall time (" << (context.full ? "full" : "quick")
       << " study)\n\nBase: " << setting_name(base) << "; one thread; wall time of the solve, "
       << "median of up to " << repeats << " repeats of solves under " << repeat_below
       << " s.\nA run counts only if its water volume changed by at most "
       << fixed(100 * max_volume_change, 0)
       << " %.\nBest error / H of the runs that count: " << fixed(best, 4) << ".\n\n"
       << table.str() << "\n"
       << cheapest.str();
  });
  std::cout << "speed_accuracy: cheapest settings (error = RMS depth error / H against Ritter; "
               "base "
            << setting_name(base) << ")\n"
            << cheapest.str() << std::flush;

  // Error against wall time, log-log, one curve per knob, each point labelled by its value.
  double y_low = 0.9 * thresholds.front(), y_high = 1.1 * thresholds.back();
  for (const TradeRun& t : trade)
    if (std::isfinite(t.error)) {
      y_low = std::min(y_low, 0.9 * t.error);
      y_high = std::max(y_high, 1.1 * t.error);
    }
  std::ostringstream gp;
  gp << "# Written by `lituya verify --case speed_accuracy`; re-run here: gnuplot "
        "speed_accuracy.gp\n"
     << "set terminal pngcairo size 1000,650 noenhanced\nset output 'speed_accuracy.png'\n"
     << "set datafile separator ','\nset logscale xy\nset grid\nset key below\n"
     << "set title "
     << post::gnuplot_text(
            "Dam break: RMS depth error against Ritter (t = 0.4 s) vs wall time\n"
            "one knob changed at a time from " +
            setting_name(base))
     << "\nset xlabel 'wall time of the solve, one thread (s)'\n"
     << "set ylabel 'RMS depth error / H'\n"
     // The data and both bounds in view, without the empty decade a log autoscale adds.
     << "set yrange [" << y_low << ":" << y_high << "]\n"
     << "set ytics (0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.1, 0.12, 0.15, 0.2, 0.3, "
        "0.5, 1)\n"
     << "set arrow from graph 0, first 0.05 to graph 1, first 0.05 nohead dt 2 lc rgb 'gray40'\n"
     << "set arrow from graph 0, first 0.10 to graph 1, first 0.10 nohead dt 3 lc rgb 'gray40'\n"
     << "plot \\\n";
  std::vector<std::pair<std::string, std::string>> curves;
  for (const Knob& k : knobs) curves.emplace_back(k.name, k.label);
  if (context.full) curves.emplace_back("combined", "combined (each knob at its cheapest)");
  for (std::size_t c = 0; c < curves.size(); ++c) {
    std::vector<std::vector<double>> knob_rows;
    const std::size_t key =
        std::find(kNames.begin(), kNames.end(), curves[c].first) - kNames.begin();
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (runs[i].knob == curves[c].first)
        knob_rows.push_back({trade[i].value, trade[i].wall_time, trade[i].error});
    std::sort(knob_rows.begin(), knob_rows.end());
    const std::string csv = "knob_" + curves[c].first + ".csv";
    write_csv(context.work / csv, "value,wall_time,error_over_h", knob_rows);
    // The knobs in gnuplot's colours, the combined runs in black.
    const std::string colour = key < kNames.size() ? "lt " + std::to_string(c + 1) : "rgb 'black'";
    gp << "  '" << csv << "' skip 1 using 2:3 with linespoints lw 2 pt 7 "
       << (key < kNames.size() ? "" : "lc ") << colour << " title "
       << post::gnuplot_text(curves[c].second) << ", \\\n";
    // Each point labelled by its value (a combined run by the error bound it was chosen for).
    gp << "  '" << csv << "' skip 1 using 2:3:(sprintf('" << (key < kNames.size() ? "" : "<= ")
       << "%.3g', $1)) with labels offset 0,0.8 tc " << colour << " font ',8' notitle"
       << (c + 1 < curves.size() ? ", \\\n" : "\n");
  }
  if (post::run_gnuplot_script(context.work / "speed_accuracy.png", gp.str()))
    result.plots.push_back(fs::relative(context.work / "speed_accuracy.png", context.report));

  // Checks of the cost and accuracy claims of user manual section 3 (README.md).
  auto knob_values = [&](const std::string& knob, double lo, double hi, bool steps) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (runs[i].knob == knob && trade[i].value >= lo && trade[i].value <= hi) {
        x.push_back(trade[i].value);
        y.push_back(steps ? static_cast<double>(runs[i].steps) : trade[i].wall_time);
      }
    return std::make_pair(x, y);
  };
  auto error_spread = [&](const std::string& knob) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (runs[i].knob == knob) {
        if (!std::isfinite(trade[i].error)) return std::numeric_limits<double>::quiet_NaN();
        lo = std::min(lo, trade[i].error);
        hi = std::max(hi, trade[i].error);
      }
    return hi - lo;
  };
  const auto [cx, cs] = knob_values("courant", 0, 1, true);
  add_check(result, "steps ~ Courant^p: p", "-", log_log_slope(cx, cs), -1.0, 0.05);
  add_check(result, "the Courant number changes the cost, not the answer: spread of error / H", "-",
            error_spread("courant"), 0.0, 0.01);
  if (context.full) {
    const auto [cw, ct] = knob_values("courant", 0, 1, false);
    add_check(result, "wall time ~ Courant^p: p", "-", log_log_slope(cw, ct), -1.0, 0.25);
    const auto [kx, ks] = knob_values("bulk_modulus", 2.15e7, 2.15e9, true);
    add_check(result, "steps ~ K_w^p, K_w = 2.15e7-2.15e9 Pa: p", "-", log_log_slope(kx, ks), 0.5,
              0.05);
    const auto [nx, nt] = knob_values("points_per_cell", 4, 16, false);
    add_check(result, "wall time ~ (points per cell)^p, 4-16: p", "-", log_log_slope(nx, nt), 1.0,
              0.3);
    const auto [hx, ht] = knob_values("cell_size", 0.005, 0.01, false);
    add_check(result, "wall time ~ h^p, h = 0.005-0.01 m: p", "-", log_log_slope(hx, ht), -3.0,
              0.5);
  }
}

}  // namespace lituya::verify
