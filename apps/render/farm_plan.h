#pragma once
// What `penumbra farm` submits: a render split into shards
// (batch/sample_split.h), as a Slurm job array of `penumbra render
// --samples` tasks and a merge job, all written into a work directory on the
// file system the cluster shares:
//
//   WORK/plan.json        this plan (a rerun resumes it, or refuses another)
//   WORK/shards.sbatch    the array job: shard $SLURM_ARRAY_TASK_ID
//   WORK/merge.sbatch     penumbra merge of every shard into the output
//   WORK/shards/shard-NNN.exr, WORK/logs/
//
// The scripts take the shard index from SLURM_ARRAY_TASK_ID only, so any
// array-job system runs them the same way (a Kubernetes indexed Job:
// SLURM_ARRAY_TASK_ID=$JOB_COMPLETION_INDEX bash shards.sbatch).
#include <cstdint>
#include <string>
#include <vector>

#include "penumbra/batch/sample_split.h"

namespace penumbra::app {

struct SlurmOptions {
  std::string partition;     // --partition; "" the cluster's default
  uint32_t gpusPerTask = 0;  // --gpus-per-task; 0 none asked for
  std::string time;          // --time limit per task; "" the partition's
  bool operator==(const SlurmOptions&) const = default;
};

struct FarmPlan {
  std::string penumbra;  // absolute path of the binary the tasks run
  // What the shards will render, as the binary computed it before submitting
  // (`render --check-only`): scene content hash, settings hash, build. A
  // shard of another identity (a rebuilt binary, an edited scene) is refused
  // and rendered again.
  std::string sceneHash, settingsHash, build;
  std::vector<std::string> renderArgs;  // `penumbra render` options of every shard
  uint32_t totalSpp = 0, blockSpp = 16;
  std::vector<render::SampleRange> shards;
  std::string out;   // the final image, absolute
  std::string work;  // the work directory, absolute
  SlurmOptions slurm;
  std::string backend;  // the merge's, for tone-mapping a PNG ("" the default)
  bool sameRender(const FarmPlan& other) const;
};

std::string shardPath(const FarmPlan& plan, size_t index);
// The sbatch scripts (bash): the array task renders its shard to a temporary
// file renamed into place (render's atomic write), so a killed task leaves
// no shard behind; Slurm requeues tasks of failed nodes (--requeue).
std::string shardScript(const FarmPlan& plan);
std::string mergeScript(const FarmPlan& plan);

std::string planToJson(const FarmPlan& plan);
// Throws penumbra::Error naming `source` and the field.
FarmPlan planFromJson(const std::string& text, const std::string& source);

// The shards whose file is absent, not a piece of this render's range, or
// damaged (batch/partial_render.h's checks); their indices, ascending.
// `problems` receives a line for each file that exists but was refused.
std::vector<size_t> missingShards(const FarmPlan& plan, std::vector<std::string>* problems);
// Slurm's --array list: "0-3", "1,4-6".
std::string arraySpec(const std::vector<size_t>& indices);
// A word quoted for bash.
std::string shellQuote(const std::string& word);

// A study split the same way (`penumbra farm study`): a job that renders
// the reference into the study's folder, a job array whose task k measures
// points parts[k] (`penumbra study --points A:B`, rows into
// OUT/points/points-A-B.csv), and a job that gathers the rows into the
// results (`--gather`). Scripts and logs in OUT/farm/.
struct StudyFarmPlan {
  std::string penumbra;
  std::vector<std::string> studyArgs;      // `penumbra study` options but --out
  std::vector<render::SampleRange> parts;  // point ranges
  std::string out;                         // the study's folder, absolute
  std::string work;                        // OUT/farm
  SlurmOptions slurm;
  bool sameStudy(const StudyFarmPlan& other) const;
};
// `points` near-equal ranges of [0, count).
std::vector<render::SampleRange> splitPoints(uint32_t count, uint32_t parts);
std::string partPath(const StudyFarmPlan& plan, size_t index);
std::string referenceScript(const StudyFarmPlan& plan);
std::string pointsScript(const StudyFarmPlan& plan);
std::string gatherScript(const StudyFarmPlan& plan);
std::string studyPlanToJson(const StudyFarmPlan& plan);
StudyFarmPlan studyPlanFromJson(const std::string& text, const std::string& source);
// The parts whose rows file is absent.
std::vector<size_t> missingParts(const StudyFarmPlan& plan);

}  // namespace penumbra::app
