// pointdriver batch: every material on every path in one process (study/batch.hpp), one CSV per
// run and a summary table.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "models/material/material.hpp"
#include "pointdriver/commands/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/format/text_format.hpp"
#include "pointdriver/output/csv_writer.hpp"
#include "pointdriver/output/run_estimate.hpp"
#include "pointdriver/study/batch.hpp"
#include "support/atomic_file.hpp"
#include "support/interrupt_signals.hpp"
#include "support/system_resources.hpp"

namespace impact::pointdriver {

namespace {

namespace fs = std::filesystem;

const CommandSpec batch_command{
    "batch",
    "Runs every material on every path in one process, over N threads (default: all cores).\n"
    "Each material is one of\n"
    "  - a material file (a JSON document with both \"density\" and \"constitutive_model\"):\n"
    "    used as it is on every path;\n"
    "  - any other JSON file, or inline JSON starting with '{': a merge patch over each path's\n"
    "    own material (e.g. '{\"constitutive_model\": {\"flow_stress\": {\"A\": 3.0e8}}}').\n"
    "Without --materials each path runs with its own material.\n"
    "Writes DIR/<path>__<material>.csv per run (columns as `pointdriver run`; not with --no-csv)\n"
    "and DIR/batch_summary.csv: path, material, steps, completed, failure cause, failure time,\n"
    "final stress_xx, plastic strain and temperature, wall time, error.\n"
    "Names: the file stems; an inline patch is set<k>, k its position in --materials.",
    "", 0,
    "Exit codes: 0 every run completed, 1 usage, 2 input error, 3 a step could not be solved in\n"
    "some run or its CSV could not be written (the error is in the summary), or the summary\n"
    "could not be written, 4 refused before the runs: the CSVs' estimated size exceeds the free\n"
    "space of DIR's file system (or ulimit -f), as pointdriver run refuses one, 130/143 stopped\n"
    "by SIGINT/SIGTERM (one line; the CSVs being written and the summary are discarded, the\n"
    "CSVs of finished runs kept).\n"};

struct MaterialEntry {
  std::string name;
  std::string origin;                ///< what messages call it: "--materials FILE" or "... set<k>"
  std::optional<Material> material;  ///< a complete material file
  Json patch;                        ///< else a merge patch over the path's material
};

std::string unique(const std::string& base, std::map<std::string, int>& seen) {
  const int n = seen[base]++;
  return n == 0 ? base : base + "_" + std::to_string(n + 1);
}

MaterialEntry read_material_entry(const std::string& arg, int index) {
  MaterialEntry e;
  if (!arg.empty() && arg.front() == '{') {
    e.patch = parse_json_text(arg, "--materials: inline JSON #" + std::to_string(index + 1));
    if (!e.patch.is_object()) throw InputError({"--materials: inline JSON must be an object"});
    e.name = "set" + std::to_string(index + 1);
    e.origin = "--materials " + e.name;
    return e;
  }
  const Json doc = load_json_file(arg);
  e.name = fs::path(arg).stem().string();
  e.origin = "--materials " + arg;
  if (doc.is_object() && doc.contains("density") && doc.contains("constitutive_model")) {
    e.material = read_material(doc, arg);
  } else if (doc.is_object()) {
    e.patch = doc;
  } else {
    throw InputError({arg + ": expected a material file or a JSON merge patch (an object)"});
  }
  return e;
}

/// The path document with `patch` merged into its material's overrides.
Json with_material_patch(Json document, const Json& patch);

/// Path `file` read with the --set patches and then material patch `m`: a problem at a key the
/// material patch set names it ("--materials p.json (over PATH): /material/overrides/..."), one
/// at a key a --set patch set that patch.
Path read_patched_path(const Json& document, const std::string& file, const std::vector<Json>& sets,
                       const MaterialEntry& m) {
  try {
    return read_path(with_material_patch(document, m.patch), file);
  } catch (const InputError& e) {
    std::vector<Json> patches = sets;
    patches.push_back(Json{{"material", {{"overrides", m.patch}}}});
    throw PatchOrigins(file, patches, [&](std::size_t k) {
      return k < sets.size() ? cli::set_patch_name(k) : m.origin;
    }).attribute(e);
  }
}

Json with_material_patch(Json document, const Json& patch) {
  Json m = document.value("material", Json());
  if (m.is_string()) m = Json{{"file", m}};
  if (m.is_object()) {
    if (!m.contains("overrides") || !m["overrides"].is_object()) m["overrides"] = Json::object();
    m["overrides"].merge_patch(patch);
    document["material"] = m;
  }
  return document;
}

std::string csv_number(double v) {
  return format_number(v, 10);
}

}  // namespace

int command_batch(const std::vector<std::string>& args) {
  Options o;
  if (const auto exit_code =
          parse_command(batch_command, o, args,
                        {{"--paths", -1, "path files (required)", "P.json"},
                         {"--materials", -1, "material files, patch files or inline patches", "M"},
                         {"--set", 1, "JSON merge patch over every path (repeatable)", "JSON"},
                         {"-o|--out", 1, "output directory (default: batch)", "DIR"},
                         {"--threads", 1, "threads (default: all cores)", "N"},
                         {"--no-csv", 0, "the summary only"}})) {
    return *exit_code;
  }
  if (!o.has("--paths")) {
    std::cerr << "pointdriver batch: missing --paths (pointdriver batch --help)\n";
    return 1;
  }
  int threads = 0;
  if (o.has("--threads")) {
    try {
      threads = std::stoi(o.get("--threads", "0"));
    } catch (const std::exception&) {
      threads = -1;
    }
    if (threads < 1) {
      std::cerr << "pointdriver batch: --threads expects a positive integer\n";
      return 1;
    }
  }
  const fs::path out_dir = o.get("--out", "batch");
  const bool write_csv = !o.has("--no-csv");

  // Paths x materials. Material files are shared by every path; patches make one Path each.
  std::vector<std::string> path_names, material_names;
  std::vector<std::unique_ptr<Path>> paths;                 // as given, one per file
  std::vector<std::vector<std::unique_ptr<Path>>> patched;  // [path][material] for patches
  std::vector<MaterialEntry> materials;
  std::vector<BatchJob> jobs;
  std::vector<std::pair<std::size_t, std::size_t>> job_index;  // (path, material)
  std::vector<Json> sets;
  std::string path_file;  // the one being read: problems at keys a --set set name the patch
  try {
    sets = cli::patches_of(o.all("--set"));
    std::map<std::string, int> seen_materials, seen_paths;
    const auto& mats = o.all("--materials");
    for (std::size_t i = 0; i < mats.size(); ++i) {
      materials.push_back(read_material_entry(mats[i], static_cast<int>(i)));
      material_names.push_back(unique(materials.back().name, seen_materials));
      if (materials.back().material) {
        for (const auto& w : materials.back().material->warnings)
          std::cerr << "pointdriver batch: warning: " << w << '\n';
      }
    }
    for (const auto& f : o.all("--paths")) {
      path_file = f;
      Json doc = load_json_file(f);
      for (const Json& p : sets) doc.merge_patch(p);
      paths.push_back(std::make_unique<Path>(read_path(doc, f)));
      for (const auto& w : cli::set_origins(f, sets).attribute(paths.back()->warnings))
        std::cerr << "pointdriver batch: warning: " << w << '\n';
      path_names.push_back(unique(fs::path(f).stem().string(), seen_paths));
      std::vector<std::unique_ptr<Path>> row;
      for (const auto& m : materials) {
        row.push_back(m.material ? nullptr
                                 : std::make_unique<Path>(read_patched_path(doc, f, sets, m)));
      }
      patched.push_back(std::move(row));
    }
  } catch (const InputError& e) {
    std::cerr << cli::set_origins(path_file, sets).attribute(e).what() << '\n';
    return cli::kExitInput;
  }
  if (materials.empty()) material_names.push_back("path_material");
  for (std::size_t p = 0; p < paths.size(); ++p) {
    if (materials.empty()) {
      jobs.push_back({paths[p].get(), &paths[p]->material.model});
      job_index.emplace_back(p, 0);
      continue;
    }
    for (std::size_t m = 0; m < materials.size(); ++m) {
      if (materials[m].material) {
        jobs.push_back({paths[p].get(), &materials[m].material->model});
      } else {
        const Path* q = patched[p][m].get();
        jobs.push_back({q, &q->material.model});
      }
      job_index.emplace_back(p, m);
    }
  }

  // Refused before a row is written when the CSVs cannot fit (as pointdriver run refuses one: a
  // leg of 1e9 steps wrote 2.3 GB in 20 s before): their estimates summed.
  if (write_csv) {
    RunEstimate all;
    for (const BatchJob& job : jobs) {
      const RunEstimate e = estimate_run(*job.path);
      all.rows += e.rows;
      all.csv_bytes += e.csv_bytes;
      all.memory_bytes = std::max(all.memory_bytes, e.memory_bytes);
      all.checked_columns = std::max(all.checked_columns, e.checked_columns);
    }
    const std::string refusal =
        run_refusal(all,
                    (out_dir / "*.csv").string() + " (" + std::to_string(jobs.size()) +
                        (jobs.size() == 1 ? " run)" : " runs)"),
                    available_output_bytes(out_dir / "batch_summary.csv"), available_memory());
    if (!refusal.empty()) {
      std::cerr << "pointdriver batch: " << refusal << '\n';
      return cli::kExitRefused;
    }
  }
  BatchOptions options;
  options.threads = threads;
  std::vector<std::unique_ptr<CsvWriter>> csvs(jobs.size());  // slot i: job i's worker only
  std::unique_ptr<AtomicFile> summary_file;
  // Ctrl-C or SIGTERM: every run stops at its next row (the sink throws, which ends that run),
  // the CSVs being written and the summary are discarded (no .tmp left), the CSVs of runs that
  // completed stay, and the batch exits 128 + the signal with one line (as pointdriver run).
  const InterruptSignals signals;
  struct Interrupted : std::runtime_error {  // the batch runner ends a run on std::exception
    Interrupted() : std::runtime_error("interrupted") {}
  };
  try {
    create_output_directory(out_dir);
    options.make_sink = [&](std::size_t i, const BatchJob& job) -> RowSink {
      CsvWriter* csv = nullptr;
      if (write_csv) {
        const auto [p, m] = job_index[i];
        const fs::path file = out_dir / (path_names[p] + "__" + material_names[m] + ".csv");
        csvs[i] = std::make_unique<CsvWriter>(file.string(), job.model->params());
        csv = csvs[i].get();
      }
      return [csv](const Row& row) {
        if (InterruptSignals::pending()) throw Interrupted{};
        if (csv) csv->write(row);
      };
    };
    options.close_sink = [&](std::size_t i) {
      if (!csvs[i]) return;
      if (!InterruptSignals::pending()) csvs[i]->close();  // else dropped: its .tmp removed
      csvs[i].reset();
    };
    summary_file = std::make_unique<AtomicFile>(out_dir / "batch_summary.csv");
  } catch (const OutputError& e) {
    std::cerr << "pointdriver batch: " << e.what() << '\n';
    return cli::kExitFailed;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<BatchResult> results = run_batch_jobs(jobs, options);
  if (const int signal = InterruptSignals::pending()) {
    summary_file.reset();  // not committed: its temporary goes
    std::size_t done = 0;
    for (const BatchResult& r : results) done += r.result.completed ? 1 : 0;
    std::cerr << "pointdriver batch: interrupted by " << InterruptSignals::name(signal)
              << "; no summary written, the CSVs of the runs that had finished kept (about " << done
              << " of " << results.size() << ")\n";
    return 128 + signal;
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const fs::path summary = summary_file->path();
  std::ostream& s = summary_file->stream();
  // A run that did not fail has no failure time: the cell is empty, not a -1 sentinel.
  s << "path,material,steps [-],completed [1 = yes],failure cause,failure time [s],"
       "final stress_xx [Pa],final plastic strain [-],final temperature [K],wall time [s],error\n";
  bool all_completed = true;
  long steps = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const BatchResult& r = results[i];
    const auto [p, m] = job_index[i];
    all_completed = all_completed && r.result.completed;
    steps += r.result.steps;
    s << csv_cell(path_names[p]) << ',' << csv_cell(material_names[m]) << ',' << r.result.steps
      << ',' << (r.result.completed ? 1 : 0) << ',' << to_string(r.result.failure) << ','
      << (r.result.failure_time >= 0.0 ? csv_number(r.result.failure_time) : "") << ','
      << csv_number(r.last.stress_path(0, 0)) << ',' << csv_number(r.last.state.plastic_strain)
      << ',' << csv_number(r.last.state.temperature) << ',' << csv_number(r.wall_time) << ','
      << csv_cell(r.result.error) << '\n';
    std::cout << std::left << std::setw(28) << path_names[p] << ' ' << std::setw(20)
              << material_names[m] << ' ' << std::right << std::setw(7) << r.result.steps
              << " steps  stress_xx " << std::setw(12) << std::setprecision(5)
              << r.last.stress_path(0, 0) << " Pa  eps_p " << std::setw(9)
              << r.last.state.plastic_strain << "  "
              << (r.result.completed ? std::string(to_string(r.result.failure)) == "none"
                                           ? "completed"
                                           : "failed: " + std::string(to_string(r.result.failure))
                                     : "UNSOLVED: " + r.result.error)
              << '\n';
  }
  const std::size_t workers =
      std::min<std::size_t>(std::max<std::size_t>(results.size(), 1),
                            threads > 0 ? static_cast<std::size_t>(threads)
                                        : std::max(1u, std::thread::hardware_concurrency()));
  try {
    summary_file->commit();
  } catch (const OutputError& e) {
    std::cerr << "pointdriver batch: " << e.what() << '\n';
    return cli::kExitFailed;
  }
  std::cout << results.size() << " runs, " << steps << " steps in " << std::setprecision(3) << total
            << " s (" << workers << " threads) -> " << summary.string() << '\n';
  return all_completed ? 0 : cli::kExitFailed;
}

}  // namespace impact::pointdriver
