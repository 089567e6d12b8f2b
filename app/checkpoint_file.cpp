#include "app/checkpoint_file.h"

#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/h5_reader.h"
#include "app/h5_writer.h"
#include "geometry/errors.h"
#include "geometry/input_text.h"

namespace linerlife {
namespace {

// The LifeRecord fields, in one table for writing and reading.
struct Field {
  const char* name;
  double LifeRecord::*member;
};
constexpr Field kFields[] = {
    {"hours", &LifeRecord::hours},
    {"lifter_height_m", &LifeRecord::lifter_height_m},
    {"crest_thickness_m", &LifeRecord::crest_thickness_m},
    {"face_angle_leading_deg", &LifeRecord::face_angle_leading_deg},
    {"face_angle_trailing_deg", &LifeRecord::face_angle_trailing_deg},
    {"top_width_m", &LifeRecord::top_width_m},
    {"min_thickness_m", &LifeRecord::min_thickness_m},
    {"liner_mass_kg_per_m", &LifeRecord::liner_mass_kg_per_m},
    {"net_power_kw", &LifeRecord::net_power_kw},
    {"toe_deg", &LifeRecord::toe_deg},
    {"shoulder_deg", &LifeRecord::shoulder_deg},
    {"direct_impact_fraction", &LifeRecord::direct_impact_fraction},
    {"impact_fraction", &LifeRecord::impact_fraction},
    {"low_lifter_height_m", &LifeRecord::low_lifter_height_m},
    {"low_face_angle_leading_deg", &LifeRecord::low_face_angle_leading_deg},
};

std::vector<double> xy(const std::vector<Eigen::Vector2d>& p) {
  std::vector<double> v;
  for (const auto& q : p) v.push_back(q.x()), v.push_back(q.y());
  return v;
}

std::vector<Eigen::Vector2d> points(const std::vector<double>& v) {
  std::vector<Eigen::Vector2d> p;
  for (size_t i = 0; i + 1 < v.size(); i += 2) p.emplace_back(v[i], v[i + 1]);
  return p;
}

/// FNV-1a (64 bit) over the bytes of everything a checkpoint stores, in one
/// fixed order, each array led by its length: written with the checkpoint
/// and recomputed from what is read back. A bit flipped on disk that leaves
/// every value plausible (a review: 4 of 40 random 4-bit flips resumed without
/// a word, one moving the power by +23 %) no longer matches.
class Digest {
 public:
  template <class T>
  Digest& add(const T& v) {
    static_assert(std::is_arithmetic_v<T>);
    const auto* b = reinterpret_cast<const unsigned char*>(&v);
    for (size_t i = 0; i < sizeof v; ++i) h_ = (h_ ^ b[i]) * 0x100000001b3ULL;
    return *this;
  }
  Digest& add(const std::string& s) {
    add(static_cast<unsigned long long>(s.size()));
    for (char ch : s) add(ch);
    return *this;
  }
  template <class T>
  Digest& add(const std::vector<T>& v) {
    add(static_cast<unsigned long long>(v.size()));
    for (const T& x : v) add(x);
    return *this;
  }
  Digest& add(const Eigen::Vector2d& p) { return add(p.x()).add(p.y()); }
  std::string hex() const { return fmt::format("fnv1a64:{:016x}", h_); }

 private:
  unsigned long long h_ = 0xcbf29ce484222325ULL;
};

std::string checkpoint_digest(const ForecastCheckpoint& c) {
  Digest d;
  d.add(c.method).add(c.t_s).add(c.have_prev).add(c.next_regular_s).add(c.next_extra).add(c.next_explicit_out_s);
  d.add(c.has_indicators).add(c.net_power_kw).add(c.toe_deg).add(c.shoulder_deg).add(c.direct_impact_fraction);
  d.add(c.impact_fraction).add(c.provider_drives);
  d.add(c.y).add(c.y_drive).add(c.y_prev).add(c.r_now).add(c.r_prev);
  // integers as they are stored (64 bit; the reader refuses a count beyond
  // an int), so a flip of any stored bit counts
  auto wide = [](const std::vector<int>& v) { return std::vector<long long>(v.begin(), v.end()); };
  d.add(c.base.shell_radius_m).add(static_cast<long long>(c.base.segments)).add(c.base.nodes);
  d.add(wide(c.base.segment_begin)).add(wide(c.base.segment_design));
  d.add(static_cast<unsigned long long>(c.history.size()));
  for (const LifeRecord& r : c.history)
    for (const Field& f : kFields) d.add(r.*(f.member));
  d.add(static_cast<unsigned long long>(c.profiles.size()));
  for (const ProfileRecord& p : c.profiles) d.add(p.hours).add(p.nodes);
  const ForecastStats& s = c.stats;
  d.add(static_cast<long long>(s.charge_redrives)).add(static_cast<long long>(s.remeshes)).add(s.cvode_steps);
  d.add(s.rhs_evals).add(s.error_test_failures).add(s.nonlinear_failures).add(static_cast<long long>(s.explicit_steps));
  d.add(s.wall_s).add(s.charge_wall_s).add(s.charge_simulated_s);
  d.add(static_cast<unsigned long long>(c.notes.size()));
  for (const DriveNote& n : c.notes) d.add(n.text).add(n.first_drive).add(n.drives);
  return d.hex();
}

}  // namespace

void write_checkpoint(const OutputDir& dir, const std::string& config_text, const ForecastCheckpoint& c) {
  const std::string tmp = dir.temp_path("checkpoint.h5");
  {
    H5Writer h5(tmp);
    h5.attr("/", "program", std::string("linerlife"));
    h5.attr("/", "version", std::string(program_version()));
    h5.attr("/", "command", std::string("checkpoint"));
    h5.text("/config", config_text);
    const std::string g = "/checkpoint";
    h5.group(g);
    h5.attr(g, "method", c.method);
    h5.attr(g, "t_s", c.t_s);
    h5.attr(g, "have_prev", static_cast<long long>(c.have_prev));
    h5.attr(g, "next_regular_s", c.next_regular_s);
    h5.attr(g, "next_extra", c.next_extra);
    h5.attr(g, "next_explicit_out_s", c.next_explicit_out_s);
    h5.attr(g, "has_indicators", static_cast<long long>(c.has_indicators));
    h5.attr(g, "net_power_kw", c.net_power_kw);
    h5.attr(g, "toe_deg", c.toe_deg);
    h5.attr(g, "shoulder_deg", c.shoulder_deg);
    h5.attr(g, "direct_impact_fraction", c.direct_impact_fraction);
    h5.attr(g, "impact_fraction", c.impact_fraction);
    h5.attr(g, "provider_drives", c.provider_drives);
    h5.attr(g, "checksum", checkpoint_digest(c));
    for (auto [name, v] : {std::pair<const char*, const std::vector<double>*>{"y", &c.y},
                           {"y_drive", &c.y_drive}, {"y_prev", &c.y_prev}, {"r_now", &c.r_now}, {"r_prev", &c.r_prev}})
      h5.dataset(g + "/" + name, *v, {v->size()});
    // the ring at the last remesh
    h5.attr(g, "shell_radius_m", c.base.shell_radius_m);
    h5.attr(g, "segments", static_cast<long long>(c.base.segments));
    const auto nodes = xy(c.base.nodes);
    h5.dataset(g + "/base_nodes", nodes, {nodes.size()});
    std::vector<long long> sb(c.base.segment_begin.begin(), c.base.segment_begin.end());
    std::vector<long long> sd(c.base.segment_design.begin(), c.base.segment_design.end());
    h5.dataset(g + "/base_segment_begin", sb, {sb.size()});
    h5.dataset(g + "/base_segment_design", sd, {sd.size()});
    // results so far
    for (const Field& f : kFields) {
      std::vector<double> v;
      for (const LifeRecord& r : c.history) v.push_back(r.*(f.member));
      h5.dataset(g + "/history_" + f.name, v, {v.size()});
    }
    std::vector<double> ph, pn;
    std::vector<long long> off{0};
    for (const ProfileRecord& p : c.profiles) {
      ph.push_back(p.hours);
      const auto v = xy(p.nodes);
      pn.insert(pn.end(), v.begin(), v.end());
      off.push_back(static_cast<long long>(pn.size()));
    }
    h5.dataset(g + "/profile_hours", ph, {ph.size()});
    h5.dataset(g + "/profile_nodes", pn, {pn.size()});
    h5.dataset(g + "/profile_offset", off, {off.size()});
    const ForecastStats& s = c.stats;
    h5.dataset(g + "/stats_int",
               std::vector<long long>{s.charge_redrives, s.remeshes, s.cvode_steps, s.rhs_evals, s.error_test_failures,
                                      s.nonlinear_failures, s.explicit_steps},
               {7});
    h5.dataset(g + "/stats_double", std::vector<double>{s.wall_s, s.charge_wall_s, s.charge_simulated_s}, {3});
    // the charge model's notes so far: text as attributes, (first drive, drives) as pairs
    std::vector<long long> nd;
    for (size_t i = 0; i < c.notes.size(); ++i) {
      h5.attr(g, fmt::format("note_{}", i), c.notes[i].text);
      nd.push_back(c.notes[i].first_drive);
      nd.push_back(c.notes[i].drives);
    }
    if (!nd.empty()) h5.dataset(g + "/note_drives", nd, {nd.size()});
    h5.close();
  }
  dir.commit(tmp, "checkpoint.h5");
}

namespace {

/// The keys whose lines differ between two configurations as config_to_toml()
/// writes them ("[section]" lines, then "key = value"), up to three, as
/// "[forecast] availability = 0.92 in the checkpoint, 0.9 now".
std::string config_difference(const std::string& was, const std::string& now) {
  auto keys = [](const std::string& text) {
    std::map<std::string, std::string> m;  // "[section] key" -> value
    std::istringstream in(text);
    std::string line, section;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      if (line[0] == '[') {
        section = line;
        continue;
      }
      const auto eq = line.find(" = ");
      if (eq != std::string::npos) m[section + " " + line.substr(0, eq)] = line.substr(eq + 3);
    }
    return m;
  };
  const auto a = keys(was), b = keys(now);
  std::vector<std::string> diffs;
  for (const auto& [k, v] : a) {
    const auto it = b.find(k);
    if (it == b.end()) diffs.push_back(fmt::format("{} = {} in the checkpoint, absent now", k, v));
    else if (it->second != v) diffs.push_back(fmt::format("{} = {} in the checkpoint, {} now", k, v, it->second));
  }
  for (const auto& [k, v] : b)
    if (!a.count(k)) diffs.push_back(fmt::format("{} absent in the checkpoint, {} now", k, v));
  std::string out;
  for (size_t i = 0; i < diffs.size() && i < 3; ++i) out += (i ? "; " : "") + printable(diffs[i]);
  if (diffs.size() > 3) out += fmt::format("; and {} more", diffs.size() - 3);
  return out;
}

}  // namespace

ForecastCheckpoint read_checkpoint(const std::string& path, const std::string& config_text, const ForecastInput& in,
                                   const ForecastSpec& spec) {
  H5Reader h5(path);
  if (!h5.exists("/checkpoint") || h5.attr_string("/", "command") != "checkpoint")
    throw InputError(path, fmt::format("{} is not a linerlife forecast checkpoint", path));
  if (h5.text("/config") != config_text)
  {
    const std::string what = config_difference(h5.text("/config"), config_text);
    throw InputError(path, fmt::format("{} was made with another configuration{}; resume with the same "
                                       "configuration, or run without --resume to start afresh",
                                       path, what.empty() ? "" : " (" + what + ")"));
  }
  if (h5.attr_string("/", "version") != program_version())
    throw InputError(path, fmt::format("{} was made by linerlife {}, this is {}; run without --resume", path,
                                       h5.attr_string("/", "version"), program_version()));
  const std::string g = "/checkpoint";
  // a damaged checkpoint: the dataset or attribute, what is wrong, and the way out
  auto damaged = [&](const std::string& name, const std::string& what) {
    // a dataset g/name, or an attribute g@name
    const std::string where = h5.exists(g + "/" + name) ? g + "/" + name : g + "@" + name;
    return InputError(path, fmt::format("{}: {}: {}; the checkpoint is damaged: run without --resume to start afresh",
                                        path, where, what));
  };
  auto xy_pairs = [&](const std::string& name) {
    const std::vector<double> v = h5.doubles(g + "/" + name);
    if (v.size() % 2 != 0) throw damaged(name, fmt::format("{} values; x, y pairs expected", v.size()));
    return v;
  };
  ForecastCheckpoint c;
  c.method = h5.attr_string(g, "method");
  c.t_s = h5.attr_double(g, "t_s");
  for (const char* flag : {"have_prev", "has_indicators"})
    if (const long long v = h5.attr_int(g, flag); v != 0 && v != 1)
      throw damaged(flag, fmt::format("{}; allowed 0 or 1", v));
  c.have_prev = h5.attr_int(g, "have_prev") != 0;
  c.next_regular_s = h5.attr_double(g, "next_regular_s");
  c.next_extra = h5.attr_int(g, "next_extra");
  c.next_explicit_out_s = h5.attr_double(g, "next_explicit_out_s");
  c.has_indicators = h5.attr_int(g, "has_indicators") != 0;
  c.net_power_kw = h5.attr_double(g, "net_power_kw");
  c.toe_deg = h5.attr_double(g, "toe_deg");
  c.shoulder_deg = h5.attr_double(g, "shoulder_deg");
  c.direct_impact_fraction = h5.attr_double(g, "direct_impact_fraction");
  c.impact_fraction = h5.attr_double(g, "impact_fraction");
  c.provider_drives = h5.attr_int(g, "provider_drives");
  c.y = h5.doubles(g + "/y");
  c.y_drive = h5.doubles(g + "/y_drive");
  c.y_prev = h5.doubles(g + "/y_prev");
  c.r_now = h5.doubles(g + "/r_now");
  c.r_prev = h5.doubles(g + "/r_prev");
  c.base.shell_radius_m = h5.attr_double(g, "shell_radius_m");
  // a count stored in 64 bits and used as an int: beyond an int it is damage
  // (the checksum hashes the int used)
  auto as_int = [&](const char* name, long long v) {
    if (v != static_cast<int>(v)) throw damaged(name, fmt::format("{}; beyond the range of a count", v));
    return static_cast<int>(v);
  };
  c.base.segments = as_int("segments", h5.attr_int(g, "segments"));
  c.base.nodes = points(xy_pairs("base_nodes"));
  for (long long v : h5.ints(g + "/base_segment_begin")) {
    if (v < 0 || v > static_cast<long long>(c.base.nodes.size()))
      throw damaged("base_segment_begin",
                    fmt::format("an entry {}; allowed 0 to {} (the stored nodes)", v, c.base.nodes.size()));
    c.base.segment_begin.push_back(static_cast<int>(v));
  }
  for (long long v : h5.ints(g + "/base_segment_design")) {
    if (v < 0 || v > 1) throw damaged("base_segment_design", fmt::format("an entry {}; allowed 0 (high) or 1 (low)", v));
    c.base.segment_design.push_back(static_cast<int>(v));
  }
  const std::vector<double> hours = h5.doubles(g + "/history_hours");
  c.history.resize(hours.size());
  for (const Field& f : kFields) {
    const std::vector<double> v = h5.doubles(g + "/history_" + f.name);
    if (v.size() != hours.size())
      throw damaged(std::string("history_") + f.name,
                    fmt::format("{} values; history_hours has {}", v.size(), hours.size()));
    for (size_t i = 0; i < v.size(); ++i) c.history[i].*(f.member) = v[i];
  }
  const std::vector<double> ph = h5.doubles(g + "/profile_hours"), pn = xy_pairs("profile_nodes");
  const std::vector<long long> off = h5.ints(g + "/profile_offset");
  // profile i is profile_nodes[off[i] .. off[i+1]): from 0, increasing in
  // x, y pairs, to the end of profile_nodes
  if (off.size() != ph.size() + 1)
    throw damaged("profile_offset", fmt::format("{} entries for {} profiles (profile_hours); profiles + 1 expected",
                                                off.size(), ph.size()));
  if (off.front() != 0) throw damaged("profile_offset", fmt::format("starts at {}; must start at 0", off.front()));
  if (off.back() != static_cast<long long>(pn.size()))
    throw damaged("profile_offset", fmt::format("ends at {}; profile_nodes has {} values", off.back(), pn.size()));
  for (size_t i = 0; i + 1 < off.size(); ++i)
    if (off[i + 1] < off[i] || off[i + 1] % 2 != 0)
      throw damaged("profile_offset", fmt::format("entry {} is {} after {}; the entries must be even and not decrease",
                                                  i + 1, off[i + 1], off[i]));
  for (size_t i = 0; i < ph.size(); ++i) {
    ProfileRecord p;
    p.hours = ph[i];
    p.nodes = points(std::vector<double>(pn.begin() + off[i], pn.begin() + off[i + 1]));
    c.profiles.push_back(std::move(p));
  }
  const std::vector<long long> si = h5.ints(g + "/stats_int");
  const std::vector<double> sd = h5.doubles(g + "/stats_double");
  if (si.size() != 7) throw damaged("stats_int", fmt::format("{} values; 7 expected", si.size()));
  if (sd.size() != 3) throw damaged("stats_double", fmt::format("{} values; 3 expected", sd.size()));
  c.stats.charge_redrives = as_int("stats_int", si[0]);
  c.stats.remeshes = as_int("stats_int", si[1]);
  c.stats.cvode_steps = si[2];
  c.stats.rhs_evals = si[3];
  c.stats.error_test_failures = si[4];
  c.stats.nonlinear_failures = si[5];
  c.stats.explicit_steps = as_int("stats_int", si[6]);
  c.stats.wall_s = sd[0];
  c.stats.charge_wall_s = sd[1];
  c.stats.charge_simulated_s = sd[2];
  const std::vector<long long> nd = h5.exists(g + "/note_drives") ? h5.ints(g + "/note_drives") : std::vector<long long>{};
  if (nd.size() % 2 != 0) throw damaged("note_drives", fmt::format("{} values; (first drive, drives) pairs expected", nd.size()));
  for (size_t i = 0; i < nd.size() / 2; ++i)
    c.notes.push_back({h5.attr_string(g, fmt::format("note_{}", i)), nd[2 * i], nd[2 * i + 1]});
  // the arrays against each other and against the run to continue
  const CheckpointProblem bad = checkpoint_problem(c, in, spec);
  if (!bad.ok()) throw damaged(bad.field, bad.what);
  // values each plausible alone, but not the ones written
  std::string stored;
  try {
    stored = h5.attr_string(g, "checksum");
  } catch (const InputError&) {
    throw damaged("checksum", "missing (a checkpoint of a build before checksums, or one damaged)");
  }
  const std::string read = checkpoint_digest(c);
  if (stored != read)
    throw damaged("checksum", fmt::format("the values read give {}, not the {} written with them", read, stored));
  c.base.finalize();
  return c;
}

}  // namespace linerlife
