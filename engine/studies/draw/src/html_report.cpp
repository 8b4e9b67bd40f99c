#include "grainlab/studies/draw/html_report.hpp"

#include <algorithm>
#include <cmath>

#include "grainlab/studies/draw/markup.hpp"
#include "grainlab/studies/paper/number_text.hpp"
#include "grainlab/studies/paper/series_stats.hpp"

namespace grainlab::report {
namespace {

const char* kStyle = R"(
body { font-family: system-ui, sans-serif; margin: 2em auto; max-width: 1200px; padding: 0 1em; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 2em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.3em 0.5em; vertical-align: top; text-align: left; }
th { background: #f3f3f3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.verdict { font-weight: bold; white-space: nowrap; }
.holds { background: #e3f4e1; } .does-not-hold { background: #fbe1de; } .inconclusive { background: #fdf3d7; }
.not-resolved { background: #e4ebf7; } .diagnostic { color: #555; }
ul.checks { margin: 0; padding-left: 1.1em; } ul.checks li { margin: 0.1em 0; }
.note { color: #555; font-size: 0.9em; }
.panels { display: flex; flex-wrap: wrap; gap: 0.5em; }
figure { margin: 1em 0 2em 0; } figcaption { color: #444; font-size: 0.9em; max-width: 70em; }
.banner { background: #fdf3d7; border: 1px solid #e0c060; padding: 0.6em 1em; }
)";

std::string verdictClass(Verdict v) {
  switch (v) {
    case Verdict::Holds: return "holds";
    case Verdict::DoesNotHold: return "does-not-hold";
    case Verdict::NotResolved: return "not-resolved";
    case Verdict::Inconclusive: return "inconclusive";
  }
  return "inconclusive";
}

// The seeds a finding was judged on (for "not resolved at N seeds").
int seedsOf(const Finding& f) {
  int n = 1;
  for (const Check& c : f.checks) n = std::max(n, c.runs);
  return n;
}

std::string checkVerdict(const Check& c) { return c.diagnostic ? "measured" : verdictText(c.verdict, c.runs); }

// Where the run's files are, relative to report.html.
std::string runDirectory(const AssemblyResult& a) { return "runs/" + a.preset + "/seed-" + std::to_string(a.seed); }

std::string td(const std::string& text, bool number = false) {
  return std::string(number ? "<td class=\"num\">" : "<td>") + escapeMarkup(text) + "</td>";
}

// "quantity at field; ..." of a run's validity warnings.
std::string warningList(const AssemblyResult& a) {
  std::string out;
  for (const ValidityWarning& w : a.summary.warnings) out += (out.empty() ? "" : "; ") + w.quantity + " at " + w.field;
  return out;
}

}  // namespace

CsvTable runsTable(std::span<const AssemblyResult> runs) {
  CsvTable t({"assembly", "seed", "status", "error", "particles", "steps", "wall_seconds", "void_ratio_after_consolidation",
              "paper_void_ratio", "peak_phi_mob_shearing_deg", "shearing_samples", "contacts_at_start", "final_axial_strain",
              "directory", "warnings"});
  for (const AssemblyResult& a : runs) {
    const double e = a.summary.voidRatioAfterConsolidation;
    const size_t n = a.shearing.size();
    t.addRow({a.preset, a.seed, std::string(toString(a.summary.status)), a.summary.error, a.summary.particles, static_cast<double>(a.summary.steps),
              a.summary.wallSeconds, e >= 0 ? e : std::nan(""), paperVoidRatio(a), finiteMax(a.shearing.column("phi_mob_deg")),
              static_cast<int>(n), n ? a.shearing.at("contacts", 0) : std::nan(""),
              n ? a.shearing.at("axial_strain", n - 1) : std::nan(""), runDirectory(a), warningList(a)});
  }
  return t;
}

CsvTable findingsTable(const std::vector<Finding>& findings) {
  // One row per check: its quantity's value (the mean over seeds), 95 % interval and verdict,
  // beside its finding's claim and overall verdict.
  CsvTable t({"number", "claim", "criterion", "verdict", "subject", "quantity", "value", "seeds", "ci_low", "ci_high",
              "holds_from", "holds_to", "check_verdict", "measured", "note", "interval", "seeds_to_resolve"});
  for (const Finding& f : findings) {
    for (const Check& c : f.checks) {
      t.addRow({f.number, f.claim, f.criterion, verdictText(f.verdict, seedsOf(f)), c.subject, c.quantity, c.value,
                c.seeds, c.ciLow, c.ciHigh, c.holdsFrom, c.holdsTo, checkVerdict(c), c.measured, f.note,
                intervalMethodText(c.interval, c.range.low, c.range.high),
                c.seedsToResolve > 0 ? CsvCell(c.seedsToResolve) : CsvCell(std::nan(""))});
    }
  }
  return t;
}

std::string renderReportHtml(std::span<const AssemblyResult> runs, const std::vector<Finding>& findings,
                             const std::vector<Figure>& figures, const ReportContext& context) {
  std::string o;
  o += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  o += "<title>grainlab: the paper's biaxial tests reproduced</title>\n<style>" + std::string(kStyle) + "</style>\n";
  o += "</head>\n<body>\n";
  o += "<h1>grainlab: principal stress rotation and fabric in biaxial tests, reproduced</h1>\n";
  o += "<p>Six DEM biaxial tests as in sections 4-6 of the paper (compaction, isotropic consolidation at 300 kPa, "
       "biaxial shearing to 20 % axial strain with σ11 held at 300 kPa): circular discs, randomly oriented "
       "elongated polygons, and elongated polygons bedded at α = 0, 30, 60, 90°. Every number and chart below is "
       "computed from these runs; the criteria are stated beside each finding.</p>\n";
  if (context.quick) {
    o += "<p class=\"banner\"><strong>Quick run.</strong> These are the -quick presets: 60 mm specimens of a few "
         "hundred particles, sampled coarsely. They test the pipeline; their fabric is noisy and the verdicts "
         "below say little about the paper's claims.</p>\n";
  }
  o += "<p>Command: <code>" + escapeMarkup(context.command) + "</code>; ";
  if (context.concurrentRuns == 0) {
    o += "the report was rebuilt from runs already on disk (each run's wall time is in the table).</p>\n";
  } else {
    o += std::to_string(context.concurrentRuns) + " run(s) at once; wall time " + fixed(context.wallSeconds, 1) +
         " s.</p>\n";
  }

  if (context.seeds > 1) {
    o += "<p>Each assembly ran with seeds 1-" + std::to_string(context.seeds) +
         " (independent random packings); figures show the mean over the seeds with its 95 % interval (Student's t, cut at the "
         "ends of a bounded quantity's range; circular for directions), and each "
         "finding is judged on that interval: it holds when the whole interval meets the criterion, does not hold "
         "when none of it does, and is not resolved at that number of seeds when the interval straddles the "
         "threshold.</p>\n";
  }
  o += "<h2 id=\"runs\">Runs</h2>\n<table>\n<tr><th>assembly</th><th>seed</th><th>status</th><th>particles</th><th>wall time (s)</th>"
       "<th>void ratio after consolidation</th><th>paper</th><th>peak φ_mob in shearing (°)</th><th>contacts at ε22 = 0</th>"
       "<th>output</th></tr>\n";
  for (const AssemblyResult& a : runs) {
    const double e = a.summary.voidRatioAfterConsolidation;
    o += "<tr>" + td(a.preset) + td(std::to_string(a.seed), true) +
         td(std::string(toString(a.summary.status)) + (a.summary.error.empty() ? "" : ": " + a.summary.error)) +
         td(std::to_string(a.summary.particles), true) + td(fixed(a.summary.wallSeconds, 1), true) +
         td(e >= 0 ? fixed(e, 3) : "-", true) + td(fixed(paperVoidRatio(a), 3), true) +
         td(fixed(finiteMax(a.shearing.column("phi_mob_deg")), 1), true) +
         td(a.shearing.size() ? fixed(a.shearing.at("contacts", 0), 0) : "-", true) + "<td><a href=\"" +
         escapeMarkup(runDirectory(a)) + "/series.csv\">series.csv</a></td></tr>\n";
  }
  o += "</table>\n";
  // A warned run is in the ensemble's figures like the others: say which ones they are.
  std::string warned;
  for (const AssemblyResult& a : runs) {
    if (a.summary.warnings.empty()) continue;
    warned += "<li>" + escapeMarkup(a.preset) + " seed " + std::to_string(a.seed) + ": ";
    for (size_t k = 0; k < a.summary.warnings.size(); ++k)
      warned += (k ? "; " : "") + escapeMarkup(describe(a.summary.warnings[k]).substr(9));  // without "warning: "
    warned += "</li>\n";
  }
  o += warned.empty() ? "<p>No run carried a validity warning (docs/validity.md in the grainlab repository).</p>\n"
                      : "<p>Runs that carried validity warnings (in the figures with the others; docs/validity.md "
                        "in the grainlab repository says what each means):</p>\n<ul>\n" + warned + "</ul>\n";
  o += "<p>Data: <a href=\"runs.csv\">runs.csv</a>. Each run's own output (series.csv, summary.json, "
       "final particles and contacts, the scene with its seed) is in runs/&lt;preset&gt;/seed-&lt;s&gt;/.</p>\n";

  o += "<h2 id=\"findings\">Findings</h2>\n<table class=\"findings\">\n<tr><th>#</th><th>the paper's claim</th>"
       "<th>measured</th><th>verdict</th></tr>\n";
  for (const Finding& f : findings) {
    o += "<tr class=\"finding\" id=\"finding-" + std::to_string(f.number) + "\"><td>" + std::to_string(f.number) +
         "</td><td>" + escapeMarkup(f.claim) + "<div class=\"note\">Criterion: " + escapeMarkup(f.criterion) +
         ".</div></td><td><ul class=\"checks\">";
    for (const Check& c : f.checks) {
      o += "<li class=\"" + (c.diagnostic ? std::string("diagnostic") : verdictClass(c.verdict)) + "\">" +
           escapeMarkup(c.subject) + ": " + escapeMarkup(c.measured) + " <em>(" + checkVerdict(c) + ")</em></li>";
    }
    o += "</ul>";
    if (!f.note.empty()) o += "<div class=\"note\">Likely reasons: " + escapeMarkup(f.note) + "</div>";
    o += "</td><td class=\"verdict " + verdictClass(f.verdict) + "\">" + verdictText(f.verdict, seedsOf(f)) + "</td></tr>\n";
  }
  o += "</table>\n<p>Data: <a href=\"findings.csv\">findings.csv</a>. A direction θ_k counts only where a_k is at "
       "least twice the noise floor 1.25·√(2/N_c); claims resting on directions below it are inconclusive, not "
       "failed.</p>\n";

  o += "<h2 id=\"figures\">Figures</h2>\n";
  for (const Figure& f : figures) {
    o += "<figure id=\"" + escapeMarkup(f.id) + "\">\n<h3>" + escapeMarkup(f.title) + "</h3>\n<div class=\"panels\">\n";
    for (const FigurePanel& p : f.panels) o += p.inlineSvg;
    if (f.panels.empty()) o += "<p>No assembly for this figure completed.</p>\n";
    o += "</div>\n<figcaption>" + escapeMarkup(f.caption) + " Data: <a href=\"" + escapeMarkup(f.id) + ".csv\">" +
         escapeMarkup(f.id) + ".csv</a>.</figcaption>\n</figure>\n";
  }
  o += "</body>\n</html>\n";
  return o;
}

}  // namespace grainlab::report
