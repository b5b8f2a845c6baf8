// `penumbra farm`: a split render or study on a Slurm cluster (farm_plan.h
// says what is submitted). `submit` and `study` validate what the tasks
// will run, write the plan and scripts and call sbatch; run again with the
// same options they resume, submitting only the parts that are missing.
// `status` shows a render's shards: done, queued and missing.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "commands.h"
#include "farm_plan.h"
#include "penumbra/batch/render_job.h"
#include "penumbra/image/image_io.h"
#include "penumbra/util/error.h"

namespace penumbra::app {
namespace {

namespace fs = std::filesystem;

struct FarmOptions {
  std::string scene, settings, size, backend;
  std::optional<uint32_t> seed;
  uint32_t spp = 64, sppPerFrame = 16, shards = 0;
  std::string out, work;
  SlurmOptions slurm;
  bool dryRun = false;
  std::vector<std::string> renderOptions;  // after `--`
  uint32_t tasks = 0;                      // farm study
  std::vector<std::string> studyOptions;   // after `--`
};

// Runs a command line (argv quoted for the shell): its exit status, its
// standard output and, apart, its standard error (a warning on stderr must
// not be read as a job id or a queue entry).
int runCommand(const std::vector<std::string>& argv, std::string& output,
               std::string* errors = nullptr) {
#ifdef _WIN32
  (void)argv;
  (void)output;
  (void)errors;
  throw Error("farm: Slurm clusters run Linux; `penumbra farm` is not available on Windows");
#else
  std::string line;
  for (const auto& a : argv) {
    if (!line.empty()) line += ' ';
    line += shellQuote(a);
  }
  char errorFile[] = "/tmp/penumbra-farm-stderr-XXXXXX";
  const int fd = ::mkstemp(errorFile);
  if (fd < 0) throw Error("farm: cannot create a temporary file for a command's errors");
  ::close(fd);
  line += " 2>" + shellQuote(errorFile);
  FILE* pipe = ::popen(line.c_str(), "r");
  if (!pipe) {
    std::remove(errorFile);
    throw Error(fmt::format("farm: cannot run '{}'", argv[0]));
  }
  output.clear();
  char buffer[4096];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
  const int status = ::pclose(pipe);
  {
    std::ifstream in(errorFile, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (errors) *errors = text.str();
  }
  std::remove(errorFile);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
#endif
}

std::string lastLine(const std::string& text) {
  std::string t = text;
  while (!t.empty() && (t.back() == '\n' || t.back() == '\r')) t.pop_back();
  const size_t nl = t.rfind('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

std::string selfPath() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("farm: cannot find the penumbra binary's own path (/proc/self/exe)");
  return self.string();
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeText(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.good()) throw Error(fmt::format("farm: cannot write '{}'", path));
  }
  fs::rename(tmp, path);
}

// sbatch --parsable prints "ID" or "ID;cluster".
std::string sbatch(const std::vector<std::string>& options, const std::string& script) {
  std::vector<std::string> argv{"sbatch", "--parsable"};
  argv.insert(argv.end(), options.begin(), options.end());
  argv.push_back(script);
  std::string output, errors;
  if (runCommand(argv, output, &errors) != 0)
    throw Error(fmt::format("farm: sbatch {} failed: {}", script, lastLine(errors)));
  const std::string id = lastLine(output).substr(0, lastLine(output).find(';'));
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw Error(fmt::format("farm: sbatch printed no job id ({})", lastLine(output)));
  return id;
}

// The states of a job's tasks still in the queue: "123_4" -> "RUNNING".
std::map<std::string, std::string> queued(const std::vector<std::string>& jobs) {
  std::map<std::string, std::string> states;
  if (jobs.empty()) return states;
  std::string list;
  for (const auto& j : jobs) {
    if (!list.empty()) list += ',';
    list += j;
  }
  std::string output, errors;
  // A job that left the queue long ago makes squeue fail ("Invalid job id"):
  // then there is nothing queued of it. Any other failure (no controller)
  // must not pass for an empty queue: a rerun would submit running shards again.
  if (runCommand({"squeue", "-h", "-r", "-j", list, "-o", "%i %T"}, output, &errors) != 0) {
    if (errors.find("Invalid job id") != std::string::npos) return states;
    throw Error(fmt::format("farm: squeue failed: {}", lastLine(errors)));
  }
  std::istringstream lines(output);
  std::string id, state;
  while (lines >> id >> state) states[id] = state;
  return states;
}

std::vector<std::string> recordedJobs(const std::string& work) {
  std::vector<std::string> jobs;
  std::istringstream in(readText(work + "/jobs.txt"));
  std::string kind, id;
  while (in >> kind >> id) jobs.push_back(id);
  return jobs;
}

void requireNothingQueued(const std::string& work);

// What goes into #SBATCH lines and Slurm's --output patterns unquoted:
// whitespace, '%' (a Slurm filename pattern) and control characters are
// refused rather than half-escaped.
void requirePlainText(const std::string& text, const char* what) {
  for (unsigned char c : text)
    if (c <= ' ' || c == '%' || c == 127)
      throw Error(
          fmt::format("farm: {} '{}' holds a space, '%' or a control character; use a "
                      "plain path or name",
                      what, text));
}

FarmPlan planFor(const FarmOptions& o) {
  if (o.shards < 1) throw Error("farm: --shards must be at least 1");
  FarmPlan plan;
  plan.penumbra = selfPath();
  plan.totalSpp = o.spp;
  plan.blockSpp = o.sppPerFrame;
  const render::SampleTree tree(o.spp, o.sppPerFrame);
  plan.shards = tree.split(o.shards);
  plan.out = fs::absolute(o.out).lexically_normal().string();
  plan.work = fs::absolute(o.work.empty() ? o.out + ".farm" : o.work).lexically_normal().string();
  plan.slurm = o.slurm;
  plan.backend = o.backend;
  requirePlainText(plan.work, "--work");
  requirePlainText(plan.out, "--out");
  requirePlainText(plan.slurm.partition, "--partition");
  requirePlainText(plan.slurm.time, "--time");
  // The final image: a known type, in a folder that exists and takes files.
  image::checkWritable(plan.out);
  // A scene file is named by its absolute path: tasks start elsewhere.
  std::error_code ec;
  const std::string scene = !o.scene.empty() && fs::is_regular_file(o.scene, ec)
                                ? fs::absolute(o.scene).string()
                                : o.scene;
  if (!scene.empty()) plan.renderArgs.insert(plan.renderArgs.end(), {"--scene", scene});
  if (!o.settings.empty())
    plan.renderArgs.insert(plan.renderArgs.end(),
                           {"--settings", fs::absolute(o.settings).string()});
  if (!o.size.empty()) plan.renderArgs.insert(plan.renderArgs.end(), {"--size", o.size});
  if (o.seed) plan.renderArgs.insert(plan.renderArgs.end(), {"--seed", std::to_string(*o.seed)});
  if (!o.backend.empty()) plan.renderArgs.insert(plan.renderArgs.end(), {"--backend", o.backend});
  for (const auto& option : o.renderOptions)
    for (const char* owned : {"--samples", "--total-spp", "--out", "--spp", "--spp-per-frame",
                              "--print-effects", "--check-only"})
      if (option == owned || option.rfind(std::string(owned) + "=", 0) == 0)
        throw Error(
            fmt::format("farm: {} is the farm's to set (give --spp, --spp-per-frame and "
                        "--out to `farm submit`)",
                        owned));
  plan.renderArgs.insert(plan.renderArgs.end(), o.renderOptions.begin(), o.renderOptions.end());
  return plan;
}

int runSubmit(const FarmOptions& o) {
  FarmPlan plan = planFor(o);
  // Everything a shard would refuse is refused here, before anything is
  // queued: the first shard's whole command is checked (options, scene,
  // split, output type), stopping short of the device; it also says what
  // the shards will render (their identity).
  std::vector<std::string> check{plan.penumbra, "render"};
  check.insert(check.end(), plan.renderArgs.begin(), plan.renderArgs.end());
  check.insert(
      check.end(),
      {"--spp-per-frame", std::to_string(plan.blockSpp), "--total-spp",
       std::to_string(plan.totalSpp), "--samples", render::formatSampleRange(plan.shards[0]),
       "--out", (fs::path(plan.out).parent_path() / "farm-check.exr").string(), "--check-only"});
  std::string output, errors;
  if (runCommand(check, output, &errors) != 0)
    throw Error(fmt::format("farm: the shards' render would fail: {}", lastLine(errors)));
  std::istringstream identity(output.substr(std::min(output.find("identity: "), output.size())));
  std::string word;
  identity >> word >> plan.sceneHash >> plan.settingsHash >> plan.build;
  if (word != "identity:" || plan.build.empty())
    throw Error(
        fmt::format("farm: the shards' render did not say what it renders ({})", lastLine(output)));
  if (o.shards > plan.shards.size())
    fmt::print("note: {} samples in frames of {} split into {} shards, not {}\n", plan.totalSpp,
               plan.blockSpp, plan.shards.size(), o.shards);

  const std::string planPath = plan.work + "/plan.json";
  std::vector<size_t> missing;
  std::vector<std::string> problems;
  if (fs::exists(planPath)) {
    const FarmPlan previous = planFromJson(readText(planPath), planPath);
    if (!previous.sameRender(plan))
      throw Error(
          fmt::format("farm: '{}' holds the plan of another render (other options, "
                      "samples, shards or output); use another --work or remove it",
                      plan.work));
    requireNothingQueued(plan.work);
    missing = missingShards(plan, &problems);
    for (const auto& p : problems) fmt::print("refused, rendered again: {}\n", p);
    fmt::print("resuming: {} of {} shards present\n", plan.shards.size() - missing.size(),
               plan.shards.size());
  } else {
    for (size_t k = 0; k < plan.shards.size(); ++k) missing.push_back(k);
  }

  const std::string shards = plan.work + "/shards.sbatch", merge = plan.work + "/merge.sbatch";
  std::vector<std::string> arrayOptions;
  if (!missing.empty()) arrayOptions.push_back("--array=" + arraySpec(missing));
  if (o.dryRun) {
    fmt::print("# {}\n{}\n# {}\n{}\n", shards, shardScript(plan), merge, mergeScript(plan));
    if (!missing.empty())
      fmt::print("would run: sbatch --parsable {} {}\n", arrayOptions[0], shards);
    fmt::print("would run: sbatch --parsable{} {}\n",
               missing.empty() ? "" : " --dependency=afterok:<shards> --kill-on-invalid-dep=yes",
               merge);
    return 0;
  }
  fs::create_directories(plan.work + "/shards");
  fs::create_directories(plan.work + "/logs");
  writeText(planPath, planToJson(plan));
  writeText(shards, shardScript(plan));
  writeText(merge, mergeScript(plan));
  std::ofstream jobs(plan.work + "/jobs.txt", std::ios::app);
  std::vector<std::string> mergeOptions;
  if (!missing.empty()) {
    const std::string id = sbatch(arrayOptions, shards);
    jobs << "shards " << id << "\n";
    fmt::print("shards: job {} (array {}, {} task(s) of {} samples in {} shards)\n", id,
               arraySpec(missing), missing.size(), plan.totalSpp, plan.shards.size());
    // A failed shard cancels the merge instead of leaving it pending.
    mergeOptions = {"--dependency=afterok:" + id, "--kill-on-invalid-dep=yes"};
  } else {
    fmt::print("shards: all {} present\n", plan.shards.size());
  }
  const std::string mergeId = sbatch(mergeOptions, merge);
  jobs << "merge " << mergeId << "\n";
  fmt::print("merge: job {} -> {}\n", mergeId, plan.out);
  return 0;
}

int runStatus(const FarmOptions& o) {
  const std::string work =
      fs::absolute(o.work.empty() ? o.out + ".farm" : o.work).lexically_normal().string();
  const std::string planPath = work + "/plan.json";
  if (!fs::exists(planPath))
    throw Error(
        fmt::format("farm status: no plan in '{}' (give --work or the --out of `farm "
                    "submit`)",
                    work));
  const FarmPlan plan = planFromJson(readText(planPath), planPath);
  const auto jobs = recordedJobs(work);
  const auto states = queued(jobs);
  std::vector<std::string> problems;
  const auto missing = missingShards(plan, &problems);
  size_t done = 0;
  for (size_t k = 0; k < plan.shards.size(); ++k) {
    std::string state = "done";
    if (std::find(missing.begin(), missing.end(), k) != missing.end()) {
      state = "missing";
      for (const auto& [id, s] : states) {
        const size_t underscore = id.find('_');  // array tasks only: "JOB_INDEX"
        if (underscore != std::string::npos && id.substr(underscore + 1) == std::to_string(k))
          state = fmt::format("{} (job {})", s, id);
      }
    } else {
      ++done;
    }
    fmt::print("shard {:3}  samples {:>12}  {}\n", k, render::formatSampleRange(plan.shards[k]),
               state);
  }
  for (const auto& p : problems) fmt::print("refused: {}\n", p);
  for (const auto& [id, s] : states)
    if (id.find('_') == std::string::npos) fmt::print("job {}: {}\n", id, s);
  fmt::print("{} of {} shards done; output {}: {}\n", done, plan.shards.size(), plan.out,
             fs::exists(plan.out) ? "written" : "not yet");
  return 0;
}

// Refuses while jobs of this work directory are still queued.
void requireNothingQueued(const std::string& work) {
  const auto stillQueued = queued(recordedJobs(work));
  if (!stillQueued.empty())
    throw Error(
        fmt::format("farm: {} task(s) of this work are still queued (e.g. job {} {}); "
                    "wait for them or scancel them, then submit again",
                    stillQueued.size(), stillQueued.begin()->first, stillQueued.begin()->second));
}

int runStudySubmit(const FarmOptions& o) {
  if (o.tasks < 1) throw Error("farm study: --tasks must be at least 1");
  for (const auto& option : o.studyOptions)
    for (const char* owned :
         {"--out", "--points", "--reference-only", "--gather", "--count-points", "--analyze"})
      if (option == owned || option.rfind(std::string(owned) + "=", 0) == 0)
        throw Error(fmt::format("farm study: {} is the farm's to set", owned));
  StudyFarmPlan plan;
  plan.penumbra = selfPath();
  plan.studyArgs = o.studyOptions;
  plan.out = fs::absolute(o.out).lexically_normal().string();
  plan.work = plan.out + "/farm";
  plan.slurm = o.slurm;
  requirePlainText(plan.out, "--out");
  requirePlainText(plan.slurm.partition, "--partition");
  requirePlainText(plan.slurm.time, "--time");
  // The study's options and scene are checked here, and its points counted.
  std::vector<std::string> count{plan.penumbra, "study"};
  count.insert(count.end(), plan.studyArgs.begin(), plan.studyArgs.end());
  count.insert(count.end(), {"--out", plan.out, "--count-points"});
  std::string output, errors;
  if (runCommand(count, output, &errors) != 0)
    throw Error(fmt::format("farm study: the study would fail: {}", lastLine(errors)));
  const std::string countText = lastLine(output);
  if (countText.empty() || countText.size() > 9 ||
      countText.find_first_not_of("0123456789") != std::string::npos)
    throw Error(fmt::format("farm study: could not count the study's points ({})", countText));
  const uint32_t points = uint32_t(std::stoul(countText));
  plan.parts = splitPoints(points, o.tasks);
  const bool ownReference = std::none_of(
      plan.studyArgs.begin(), plan.studyArgs.end(),
      [](const std::string& a) { return a == "--reference" || a.rfind("--reference=", 0) == 0; });

  const std::string planPath = plan.work + "/plan.json";
  std::vector<size_t> missing;
  if (fs::exists(planPath)) {
    if (!studyPlanFromJson(readText(planPath), planPath).sameStudy(plan))
      throw Error(
          fmt::format("farm study: '{}' holds the plan of another study; use another "
                      "--out or remove it",
                      plan.work));
    requireNothingQueued(plan.work);
    missing = missingParts(plan);
    fmt::print("resuming: {} of {} parts present\n", plan.parts.size() - missing.size(),
               plan.parts.size());
  } else {
    for (size_t k = 0; k < plan.parts.size(); ++k) missing.push_back(k);
  }
  const std::string reference = plan.work + "/reference.sbatch",
                    array = plan.work + "/points.sbatch", gather = plan.work + "/gather.sbatch";
  if (o.dryRun) {
    if (ownReference) fmt::print("# {}\n{}\n", reference, referenceScript(plan));
    fmt::print("# {}\n{}\n# {}\n{}\n", array, pointsScript(plan), gather, gatherScript(plan));
    fmt::print("would run: sbatch{} --array={} {}, then {} after it\n",
               ownReference ? " (after the reference)" : "", arraySpec(missing), array, gather);
    return 0;
  }
  fs::create_directories(plan.work + "/logs");
  writeText(planPath, studyPlanToJson(plan));
  writeText(array, pointsScript(plan));
  writeText(gather, gatherScript(plan));
  std::ofstream jobs(plan.work + "/jobs.txt", std::ios::app);
  std::vector<std::string> after;
  if (ownReference && !missing.empty()) {
    // Cached in the study's folder: a rerun finds it and renders nothing.
    writeText(reference, referenceScript(plan));
    const std::string id = sbatch({}, reference);
    jobs << "reference " << id << "\n";
    fmt::print("reference: job {}\n", id);
    after = {"--dependency=afterok:" + id, "--kill-on-invalid-dep=yes"};
  }
  std::vector<std::string> gatherOptions;
  if (!missing.empty()) {
    std::vector<std::string> options = after;
    options.push_back("--array=" + arraySpec(missing));
    const std::string id = sbatch(options, array);
    jobs << "points " << id << "\n";
    fmt::print("points: job {} (array {}: {} points in {} parts)\n", id, arraySpec(missing), points,
               plan.parts.size());
    gatherOptions = {"--dependency=afterok:" + id, "--kill-on-invalid-dep=yes"};
  }
  const std::string gatherId = sbatch(gatherOptions, gather);
  jobs << "gather " << gatherId << "\n";
  fmt::print("gather: job {} -> {}/results.csv\n", gatherId, plan.out);
  return 0;
}

}  // namespace

Command addFarmCommand(CLI::App& app) {
  auto o = std::make_shared<FarmOptions>();
  auto* farm = app.add_subcommand("farm", "Split a render across a Slurm cluster and merge it");
  farm->require_subcommand(1);
  auto* submit = farm->add_subcommand(
      "submit", "Submit a render as a Slurm job array of shards and a merge job (or resume one)");
  submit->add_option("--scene", o->scene, "Built-in scene or scene file");
  submit->add_option("--settings", o->settings,
                     "Render settings file (penumbra render --settings)");
  submit->add_option("--size", o->size, "Image size WIDTHxHEIGHT");
  submit->add_option("--seed", o->seed, "Random seed");
  submit->add_option("--backend", o->backend, "Backend the shards render on");
  submit->add_option("--spp", o->spp, "Samples per pixel of the whole render")
      ->check(CLI::Range(1u, render::kMaxSamplesPerPixel))
      ->capture_default_str();
  submit->add_option("--spp-per-frame", o->sppPerFrame, "Samples per GPU frame (a shard's unit)")
      ->check(CLI::Range(1u, render::PathTracer::kMaxSamplesPerFrame))
      ->capture_default_str();
  submit->add_option("--shards", o->shards, "Number of shards (array tasks)")->required();
  submit->add_option("--out", o->out, "Final image (.exr or .png) on the shared file system")
      ->required();
  submit->add_option("--work", o->work,
                     "Work directory for plan, scripts, shards and logs "
                     "(default OUT.farm)");
  submit->add_option("--partition", o->slurm.partition, "Slurm partition");
  submit->add_option("--gpus-per-task", o->slurm.gpusPerTask, "GPUs each shard asks for");
  submit->add_option("--time", o->slurm.time, "Time limit of each task (Slurm's format)");
  submit->add_flag("--dry-run", o->dryRun, "Print the scripts and sbatch calls, submit nothing");
  submit->add_option("render-options", o->renderOptions,
                     "More `penumbra render` options for every shard, after --");
  auto* study = farm->add_subcommand(
      "study", "Submit a study as a reference job, a job array over its points and a gather job");
  study->add_option("--tasks", o->tasks, "Number of array tasks the points are split into")
      ->required();
  study->add_option("--out", o->out, "The study's folder (results, images, parts, farm/)")
      ->required();
  study->add_option("--partition", o->slurm.partition, "Slurm partition");
  study->add_option("--gpus-per-task", o->slurm.gpusPerTask, "GPUs each task asks for");
  study->add_option("--time", o->slurm.time, "Time limit of each task (Slurm's format)");
  study->add_flag("--dry-run", o->dryRun, "Print the scripts and sbatch calls, submit nothing");
  study->add_option("study-options", o->studyOptions,
                    "`penumbra study` options (scene, sweep, reference), after --");
  auto* status = farm->add_subcommand("status", "Show a farm render's shards and jobs");
  status->add_option("--out", o->out, "The final image given to `farm submit`");
  status->add_option("--work", o->work, "Its work directory (default OUT.farm)");
  return [o, submit, study, status]() -> int {
    if (submit->parsed()) return runSubmit(*o);
    if (study->parsed()) return runStudySubmit(*o);
    if (status->parsed()) {
      if (o->out.empty() && o->work.empty()) throw Error("farm status: give --out or --work");
      return runStatus(*o);
    }
    return 1;
  };
}

}  // namespace penumbra::app
