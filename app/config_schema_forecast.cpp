// The [forecast] keys (issue 5; docs/configuration.md).
#include "app/config.h"
#include "app/config_schema_util.h"
#include "forecast/calendar.h"

namespace linerlife {

namespace {

KeySpec date_key(const char* name, const char* help, const char* def,
                 std::function<void(Config&, const CivilDate&)> set, std::function<CivilDate(const Config&)> get) {
  KeySpec k;
  k.section = "forecast";
  k.name = name;
  k.kind = ConfigValue::Kind::Date;
  k.help = help;
  k.default_value = ConfigValue::Date(def);
  k.set = [set](Config& c, const ConfigValue& v) {
    CivilDate d;
    parse_iso_date(v.text, d);  // the loader produced it from a TOML date, so it is valid
    set(c, d);
  };
  k.get = [get](const Config& c) -> std::optional<ConfigValue> { return ConfigValue::Date(iso_date(get(c))); };
  return k;
}

}  // namespace

void add_forecast_keys(Schema& s) {
  s.sections.push_back("forecast");
  auto& K = s.keys;
  K.push_back(string_key("forecast", "method", "Life integration: the CVODE ODE, the thesis' amplification, or explicit Euler",
                         {"ode", "amplify", "euler"}, "ode",
                         [](Config& c, const std::string& v) {
                           c.forecast.method = v == "amplify" ? ForecastMethod::Amplify
                                               : v == "euler" ? ForecastMethod::Euler
                                                              : ForecastMethod::Ode;
                         },
                         [](const Config& c) { return std::string(method_name(c.forecast.method)); }));
  K.push_back(string_key("forecast", "integrator", "CVODE family: Adams (non-stiff, the default) or BDF", {"adams", "bdf"},
                         "adams", [](Config& c, const std::string& v) { c.forecast.integrator = v; },
                         [](const Config& c) { return c.forecast.integrator; }));
  // The floors of rtol, atol and refresh_tol_m (a review, 2026-12-06): rtol =
  // atol = 1e-20 failed inside CVODE (exit 3, CV_TOO_MUCH_ACC, naming no key),
  // rtol = 1e-16 ran but moved the life 4 %, beyond the 1e-3..1e-6 study of
  // docs/validation/forecast.md; refresh_tol_m = 1e-9 re-drove the charge 800
  // times in its first 0.017 h (10 um: about 5,000 drives, minutes, for the
  // bundled mill's 50 mm of wear).
  K.push_back(real_key("forecast", "rtol", "-", "CVODE relative tolerance", 1e-10, 0.1, false, false, 1e-4,
                       [](Config& c, double v) { c.forecast.rtol = v; }, [](const Config& c) { return c.forecast.rtol; }));
  K.push_back(real_key("forecast", "atol", "m", "CVODE absolute tolerance on the recession depth", 1e-12, 1e-3, false, false,
                       1e-6, [](Config& c, double v) { c.forecast.atol = v; },
                       [](const Config& c) { return c.forecast.atol; }));
  K.push_back(real_key("forecast", "refresh_tol_m", "m",
                       "Re-drive the charge model once the profile has moved this far since the last drive", 1e-5, 0.05,
                       false, false, 0.002, [](Config& c, double v) { c.forecast.refresh_tol_m = v; },
                       [](const Config& c) { return c.forecast.refresh_tol_m; }));
  K.push_back(string_key("forecast", "refresh",
                         "When to re-drive the charge: \"auto\" (refresh_tol_m) or \"always\" (every right-hand side)",
                         {"auto", "always"}, "auto",
                         [](Config& c, const std::string& v) { c.forecast.refresh_always = v == "always"; },
                         [](const Config& c) { return std::string(c.forecast.refresh_always ? "always" : "auto"); }));
  K.push_back(string_key("forecast", "rate_model",
                         "Rates between drives: \"frozen\" (those of the last drive) or \"secant\" (linear along the path of the last two "
                         "drives; smooth models only, docs/validation/forecast.md)",
                         {"secant", "frozen"}, "frozen", [](Config& c, const std::string& v) { c.forecast.rate_model = v; },
                         [](const Config& c) { return c.forecast.rate_model; }));
  K.push_back(int_key("forecast", "rate_smoothing_passes",
                      "Flux-form 1-2-1 smoothing passes over the rate field, at least (more where rate_smoothing_m asks)",
                      0, 50, false, [](Config& c, long long v) { c.forecast.rate_smoothing_passes = static_cast<int>(v); },
                      [](const Config& c) { return static_cast<long long>(c.forecast.rate_smoothing_passes); }, 2));
  K.push_back(real_key("forecast", "rate_smoothing_m", "m",
                       "Smooth the rate field over at least this length along the surface (the passes' standard "
                       "deviation on elements of element_size_m; 0: rate_smoothing_passes alone)",
                       0.0, 0.2, false, false, 0.01, [](Config& c, double v) { c.forecast.rate_smoothing_m = v; },
                       [](const Config& c) { return c.forecast.rate_smoothing_m; }));
  K.push_back(real_key("forecast", "revolutions_per_drive", "rev", "Mill revolutions averaged per charge drive", 0.5,
                       1000.0, false, false, 10.0, [](Config& c, double v) { c.forecast.revolutions_per_drive = v; },
                       [](const Config& c) { return c.forecast.revolutions_per_drive; }));
  K.push_back(real_key("forecast", "remesh_depth_m", "m",
                       "Remesh once a node receded this far (0: half the element size)", 0.0, 0.1, false, false, 0.0,
                       [](Config& c, double v) { c.forecast.remesh_depth_m = v; },
                       [](const Config& c) { return c.forecast.remesh_depth_m; }));
  K.push_back(real_key("forecast", "min_lifter_height_m", "m", "Relining criterion: lifter height above the plate",
                       0.0, 2.0, false, false, 0.075, [](Config& c, double v) { c.forecast.min_lifter_height_m = v; },
                       [](const Config& c) { return c.forecast.min_lifter_height_m; }));
  K.push_back(real_key("forecast", "min_plate_thickness_m", "m", "Relining criterion: thinnest point of the liner",
                       0.0, 1.0, true, false, 0.025, [](Config& c, double v) { c.forecast.min_plate_thickness_m = v; },
                       [](const Config& c) { return c.forecast.min_plate_thickness_m; }));
  K.push_back(real_key("forecast", "max_face_angle_leading_deg", "deg",
                       "Relining criterion: leading face angle from the radial", 0.0, 90.0, true, false, 60.0,
                       [](Config& c, double v) { c.forecast.max_face_angle_leading_deg = v; },
                       [](const Config& c) { return c.forecast.max_face_angle_leading_deg; }));
  K.push_back(real_key("forecast", "max_operating_hours", "h",
                       "Horizon: a life longer than this is reported as not reached", 0.0, 1e6, true, false, 50000.0,
                       [](Config& c, double v) { c.forecast.max_operating_hours = v; },
                       [](const Config& c) { return c.forecast.max_operating_hours; }));
  K.push_back(date_key("start_date", "First day of operation of the new liner", "2027-01-01",
                       [](Config& c, const CivilDate& d) { c.forecast.calendar.start = d; },
                       [](const Config& c) { return c.forecast.calendar.start; }));
  K.push_back(real_key("forecast", "availability", "-",
                       "Fraction of calendar time the mill runs, outside planned shutdowns", 0.0, 1.0, true, false, 0.92,
                       [](Config& c, double v) { c.forecast.calendar.availability = v; },
                       [](const Config& c) { return c.forecast.calendar.availability; }));
  {
    KeySpec k;
    k.section = "forecast";
    k.name = "shutdowns";
    k.kind = ConfigValue::Kind::Shutdowns;
    k.help = "Planned shutdowns, whole days from each start date";
    k.default_value = ConfigValue::List({});
    k.set = [](Config& c, const ConfigValue& v) { c.forecast.calendar.shutdowns = v.shutdowns; };
    k.get = [](const Config& c) -> std::optional<ConfigValue> {
      return ConfigValue::List(c.forecast.calendar.shutdowns);
    };
    K.push_back(k);
  }
  K.push_back(real_key("forecast", "throughput_t_per_h", "t/h", "Ore throughput while running (for tonnes per liner)",
                       0.0, 1e5, false, false, 0.0, [](Config& c, double v) { c.forecast.throughput_t_per_h = v; },
                       [](const Config& c) { return c.forecast.throughput_t_per_h; }));
  // (the floors of amplification, amplify_revolutions, euler_step_h and
  // output_interval_h keep a run finite: 1, 1e-9 revolutions, 1e-6 h and
  // 1e-6 h ran without end or out of memory; at 0.1 revolutions and A = 1e3
  // a step is 0.16 h of the bundled mill, some 42,000 steps for its life:
  // hours of wall time, but an end; the studies of
  // docs/validation/forecast.md use A >= 1e5, steps >= 50 h)
  K.push_back(real_key("forecast", "amplification", "-", "Amplify method: wear multiplier A (thesis Table B.1)", 1e3,
                       1e12, false, false, 1e7, [](Config& c, double v) { c.forecast.amplification = v; },
                       [](const Config& c) { return c.forecast.amplification; }));
  K.push_back(real_key("forecast", "amplify_revolutions", "rev",
                       "Amplify method: revolutions simulated per step (Qiu 2001: about 1.5)", 0.1, 100.0, false, false,
                       1.5, [](Config& c, double v) { c.forecast.amplify_revolutions = v; },
                       [](const Config& c) { return c.forecast.amplify_revolutions; }));
  K.push_back(real_key("forecast", "euler_step_h", "h", "Euler method: fixed step", 1.0, 10000.0, false, false, 100.0,
                       [](Config& c, double v) { c.forecast.euler_step_h = v; },
                       [](const Config& c) { return c.forecast.euler_step_h; }));
  K.push_back(real_key("forecast", "checkpoint_interval_s", "s",
                       "Wall time between checkpoints of a forecast run with --out (0: after every charge drive)", 0.0,
                       86400.0, false, false, 60.0, [](Config& c, double v) { c.forecast.checkpoint_interval_s = v; },
                       [](const Config& c) { return c.forecast.checkpoint_interval_s; }));
  K.push_back(real_key("forecast", "output_interval_h", "h", "History and profile snapshots at least this often", 10.0,
                       1e5, false, false, 100.0, [](Config& c, double v) { c.forecast.output_interval_h = v; },
                       [](const Config& c) { return c.forecast.output_interval_h; }));
}

}  // namespace linerlife
