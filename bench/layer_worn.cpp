// bench_layer_worn: a charge model on the worn profiles of a forecast
// (docs/models/layer-worn.md).
//
//   bench_layer_worn FORECAST.h5 [options]
//     --model NAME      charge model (layer, dem, empirical; default: the run's)
//     --variant V       layer model version (1.0, 1.1, 1.2)
//     --revs N          revolutions averaged (default: the forecast's per drive)
//     --every K         every K-th profile (default 1)
//     --only i,j,...    these profile indices only
//     --blend i,j,n     n + 1 profiles blended from profile i to profile j
//     --csv-dir DIR     also write each profile used as a profile CSV (docs/profile-csv.md)
//     --rings 1         the whole rings of the file instead (/surface and /final_surface, each
//                       design's first segment repeated: a hi-lo ring keeps its low lifters)
//     --unheld-mu MU    layer model study options (docs/models/layer.md §3, "The release
//     --pocket-balls P  study"): ModelSpec::unheld_friction_coefficient, held_pocket_balls
//     --lifter-slide B  [model] lifter_slide, on or off
//     --beta B          version 1.2's en-masse share in eq. 4.14 (ModelSpec::inner_radius_beta)
//     --beta-iterate N  N more runs of each profile, each with beta = 1 - the previous run's
//                       airborne fraction (docs/models/layer-worn.md, "The en-masse share of
//                       eq. 4.14"); one row per run
//
// FORECAST.h5 is the results file of `linerlife forecast --out DIR`. Prints one
// tab-separated row per profile: hours, lifter metrics, and the indicators.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/charge_cases.h"
#include "bench/worn_profiles.h"
#include "charge/charge_model.h"
#include "geometry/measured_profile.h"
#include "geometry/metrics.h"

using namespace linerlife;

static std::vector<int> parse_ints(const std::string& s) {
  std::vector<int> v;
  std::stringstream ss(s);
  std::string tok;
  while (std::getline(ss, tok, ',')) v.push_back(std::stoi(tok));
  return v;
}

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FORECAST.h5 [--model M] [--variant V] [--revs N] [--every K] [--only i,j] "
                         "[--blend i,j,n] [--csv-dir DIR] [--unheld-mu MU] [--pocket-balls P] [--lifter-slide on|off] "
                         "[--beta B] [--beta-iterate N]\n", argv[0]);
    return 2;
  }
  const bench::WornHistory w = bench::read_worn_history(argv[1]);
  Config c = w.config;
  std::string model = c.model.charge, csv_dir;
  double revs = c.forecast.revolutions_per_drive;
  int every = 1, beta_passes = 0;
  bool rings = false;
  std::vector<int> only, blend;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--model") model = v;
    else if (k == "--variant") c.model.variant = v;
    else if (k == "--revs") revs = std::stod(v);
    else if (k == "--every") every = std::stoi(v);
    else if (k == "--only") only = parse_ints(v);
    else if (k == "--blend") blend = parse_ints(v);
    else if (k == "--csv-dir") csv_dir = v;
    else if (k == "--beta-iterate") beta_passes = std::stoi(v);
    else if (k == "--rings") rings = v == "1";
    else if (!bench::set_study_option(c.model, k, v)) {
      std::fprintf(stderr, "unknown option or value: %s %s\n", k.c_str(), v.c_str());
      return 2;
    }
  }
  const double R = c.mill.shell_radius_m();
  const int S = c.liner.segments;
  struct Job {
    std::string label;
    std::vector<Eigen::Vector2d> profile;
    std::optional<LinerSurface> ring;  // --rings: the whole ring
  };
  std::vector<Job> jobs;
  if (rings) {
    for (const char* g : {"/surface", "/final_surface"}) {
      std::vector<std::vector<Eigen::Vector2d>> designs;
      LinerSurface s = bench::read_ring(argv[1], g, R, &designs);
      // with --csv-dir: each design's profile (a hi-lo ring's low lifter as _design1)
      for (size_t d = 1; d < designs.size() && !csv_dir.empty(); ++d) {
        std::FILE* f = std::fopen(fmt::format("{}/profile_{}_design{}.csv", csv_dir, g + 1, d).c_str(), "w");
        if (!f) continue;
        fmt::print(f, "# segment profile of design {} of {} in {}\nx_m,y_m\n", d, g, argv[1]);
        for (const auto& p : segment_to_profile_xy(designs[d], R, 0.0, 2 * M_PI / S)) fmt::print(f, "{:.6f},{:.6f}\n", p.x(), p.y());
        std::fclose(f);
      }
      jobs.push_back({g + 1, designs[0], std::move(s)});
    }
  } else if (blend.size() == 3) {
    for (int q = 0; q <= blend[2]; ++q) {
      const double t = static_cast<double>(q) / blend[2];
      jobs.push_back({fmt::format("{:.3f}", t),
                      bench::blend_profiles(w.profiles.at(blend[0]), w.profiles.at(blend[1]), t, S), std::nullopt});
    }
  } else {
    for (size_t k = 0; k < w.profiles.size(); ++k) {
      const bool take = only.empty() ? k % every == 0 || k + 1 == w.profiles.size()
                                     : std::find(only.begin(), only.end(), static_cast<int>(k)) != only.end();
      if (take) jobs.push_back({fmt::format("{:.0f}", w.hours[k]), w.profiles[k], std::nullopt});
    }
  }
  fmt::print("# {} variant {} revs {} on {} ({} profiles)\n", model, c.model.variant, revs, argv[1], jobs.size());
  fmt::print("hours\tlifter_m\tlead_deg\tD_eff_m\tr_i_m\ttoe\tshoulder\tcom_deg\tcom_r\tlayers\ttraj\tnet_kW\talt_kW\t"
             "open\twall_s\tbeta\tairborne\n");
  for (const Job& j : jobs) {
    const LinerSurface s = j.ring ? *j.ring : bench::ring_of(R, S, j.profile);
    const SegmentMetrics m = segment_metrics(s, 0, c.mill.rotation, 7800.0);
    if (!csv_dir.empty()) {
      const auto xy = segment_to_profile_xy(j.profile, R, 0.0, 2 * M_PI / S);
      std::FILE* f = std::fopen(fmt::format("{}/profile_{}.csv", csv_dir, j.label).c_str(), "w");
      if (f) {
        fmt::print(f, "# segment profile at {} ({}), lifter {:.4f} m, leading face {:.2f} deg\nx_m,y_m\n", j.label,
                   argv[1], m.lifter_height_m, m.face_angle_leading_deg);
        for (const auto& p : xy) fmt::print(f, "{:.6f},{:.6f}\n", p.x(), p.y());
        std::fclose(f);
      }
    }
    ChargeInput in;
    in.mill = c.mill;
    in.charge = c.charge;
    in.model = c.model;
    in.model.charge = model;
    in.surface = &s;
    in.revolutions = revs;
    in.seed = 1;
    for (int pass = 0; pass <= (model == "layer" ? beta_passes : 0); ++pass) {
      const auto t0 = std::chrono::steady_clock::now();
      try {
        // CHARGE_DUMP=PREFIX: the last revolution's element positions, PREFIX_LABEL.csv
        const char* dump = std::getenv("CHARGE_DUMP");
        in.record_snapshot = dump != nullptr;
        const ChargeResult r = find_charge_model(model).make()->run(in);
        if (dump && !r.snapshots.empty()) {
          std::FILE* f = std::fopen(fmt::format("{}_{}.csv", dump, j.label).c_str(), "w");
          for (size_t q = 0; f && q < r.snapshots.size(); ++q)
            for (size_t i = 0; i < r.snapshots[q].position.size(); ++i)
              fmt::print(f, "{},{},{},{}\n", q, r.snapshots[q].position[i].x(), r.snapshots[q].position[i].y(),
                         r.snapshots[q].state[i]);
          if (f) std::fclose(f);
        }
        const Indicators& I = r.indicators;
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        fmt::print("{}\t{:.4f}\t{:.2f}\t{:.4f}\t{:.3f}\t{:.1f}\t{:.1f}\t{:.1f}\t{:.3f}\t{}\t{}\t{:.0f}\t{:.0f}\t{}\t{:.2f}"
                   "\t{:.4f}\t{:.4f}\n",
                   j.label, m.lifter_height_m, m.face_angle_leading_deg, I.diameter_eff_m, I.inner_radius_m, I.toe_deg,
                   I.shoulder_deg, I.com_angle_deg, I.com_radius_m, I.n_layers, I.n_trajectories, I.net_power_kw,
                   I.alt_net_power_kw, I.layer_speed_rpm.size(), wall, r.stats.inner_radius_beta,
                   r.stats.airborne_fraction);
        for (const auto& n : r.notes) fmt::print(stderr, "{}: note: {}\n", j.label, n);
        if (std::getenv("LAYER_SPEEDS")) {
          fmt::print(stderr, "{}: layer speeds [rpm]:", j.label);
          for (double v : I.layer_speed_rpm) fmt::print(stderr, " {:.2f}", v);
          fmt::print(stderr, "\n");
        }
        in.model.inner_radius_beta = 1.0 - r.stats.airborne_fraction;
      } catch (const std::exception& e) {
        fmt::print("{}\t{:.4f}\t{:.2f}\tFAILED: {}\n", j.label, m.lifter_height_m, m.face_angle_leading_deg, e.what());
        break;
      }
    }
    std::fflush(stdout);
  }
  return 0;
}
