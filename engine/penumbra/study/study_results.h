#pragma once
// A study's results on disk: results.csv (one row per technique x spp x
// seed, a header row first; the columns scripts rely on are documented in
// docs/ARCHITECTURE.md "Studies") and results.json (the same rows with the
// study's context, the summaries and the answers).
#include <string>
#include <vector>

#include "penumbra/study/study_analysis.h"
#include "penumbra/study/study_runner.h"

namespace penumbra::study {

// Where and how the study ran, written with every results file.
struct StudyContext {
  std::string scene;
  uint32_t width = 0, height = 0;
  std::string device, api, backend, commit;
  std::string referenceSource;
  uint32_t referenceSpp = 0, referenceSeed = 0;
  double referenceNoiseRelMse = -1.0;
  double budgetMs = 33.3;
};

// results.csv's header: the technique's label, a column per study axis
// (studyAxes()), then the point and what was measured.
const std::string& resultsCsvHeader();

// The file name (no extension) of a point's image under images/: the
// technique's label with anything but letters, digits and dots as '_',
// then "-spp" and the count, e.g. "mis_clamp_10-spp16".
std::string imageName(const std::string& technique, uint32_t spp);

Measurement measurement(const StudyRow& row);
std::string resultsCsv(const std::vector<StudyRow>& rows);
// The rows of a results.csv (its header must hold at least the columns
// technique, spp, seed, gpu_ms, relmse, mape, ssim, bias, in any order).
// Throws penumbra::Error naming `source` and the line on anything malformed.
std::vector<Measurement> parseResultsCsv(const std::string& text, const std::string& source);
// The rows of a results.csv written for some of `points` (a part of a split
// study, `penumbra study --points`), each matched to its point by technique
// label, spp and seed; every column resultsCsv writes is read back exactly.
// Throws penumbra::Error naming `source` and the line on anything malformed
// or a row that is no point of the study.
std::vector<StudyRow> parseStudyRows(const std::string& text, const std::string& source,
                                     const std::vector<StudyPoint>& points);
// Each summary names its preview, images/<imageName>.png.
std::string resultsJson(const StudyContext& context, const std::vector<StudyRow>& rows,
                        const std::vector<PointSummary>& summaries);

}  // namespace penumbra::study
