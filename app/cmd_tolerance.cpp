// gearsim tolerance: the accuracy tolerances of one gear at one quality class, after DIN 3961/3962
// and ISO 1328-1:1995 (geometry/tolerance.hpp), as a table with every intermediate value or as
// JSON. Units here are the standards' own: mm in, µm out.
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/tolerance_report.hpp"
#include "geometry/tolerance.hpp"

namespace gearsim::app {
namespace {

struct ToleranceOptions {
  ToleranceInput input;
  double contact_ratio = 0.0;  // copied into input when given
  std::string standard = "both";
  bool json = false;
};

// The text report: inputs, the paper's formulas per standard, ISO's own formulas, the answer.
void print_text(const ToleranceOptions& o, const std::vector<ToleranceResult>& paper, const ToleranceResult* iso_own) {
  const ToleranceInput& in = o.input;
  std::cout << "Gear accuracy tolerances: m_n = " << in.module_mm << " mm, z = " << in.teeth << ", d = " << in.reference_diameter_mm
            << " mm, quality class " << in.quality;
  if (in.contact_ratio) std::cout << ", contact ratio ε_γ = " << *in.contact_ratio;
  std::cout << "\n\nPaper eqs (1)-(5) (reference 000, section 3), class-5 values graded by:\n";
  for (const ToleranceResult& r : paper) print_tolerance_grading(std::cout, r);
  print_tolerance_table(std::cout, paper);

  if (iso_own != nullptr) {
    std::cout << "\nISO 1328-1:1995's own class-5 formulas (clause 6, Annex A, Annex B):\n";
    print_tolerance_grading(std::cout, *iso_own);
    print_tolerance_table(std::cout, {*iso_own});
    if (iso_own->composite_k) {
      std::cout << "  Annex A factor K = 0.2(ε_γ + 4)/ε_γ (0.4 from ε_γ = 4) = " << fixed(*iso_own->composite_k, 4) << "\n";
    } else {
      std::cout << "  f_i' and F_i' (Annex A) need the contact ratio: pass --contact-ratio.\n";
    }
  }

  std::cout << "\n";
  for (const ToleranceResult& r : paper) {
    std::cout << "Single flank error F_i' (paper eq 5) = " << fixed(*r.single_flank_error_um, 1) << " µm  [" << standard_name(r.standard)
              << ", class " << r.quality << ", step factor " << fixed(r.step_factor, 4) << " from class 5, unrounded "
              << fixed(r.at("single_flank_composite").unrounded_um, 3) << " µm]\n";
  }
  if (iso_own != nullptr && iso_own->single_flank_error_um) {
    std::cout << "Total single-flank composite F_i' (ISO 1328-1 formulas) = " << fixed(*iso_own->single_flank_error_um, 1) << " µm\n";
  }
}

// Computes what --standard asks for and prints it.
void run(ToleranceOptions& o, bool has_contact_ratio) {
  if (has_contact_ratio) o.input.contact_ratio = o.contact_ratio;
  if (o.json) {
    std::cout << tolerance_json(o.input, o.standard).dump(2) << "\n";
    return;
  }
  std::vector<ToleranceResult> paper;
  if (o.standard != "iso") paper.push_back(paper_tolerances(o.input, ToleranceStandard::Din3961));
  std::unique_ptr<ToleranceResult> iso_own;
  if (o.standard != "din") {
    paper.push_back(paper_tolerances(o.input, ToleranceStandard::Iso1328));
    iso_own = std::make_unique<ToleranceResult>(iso1328_tolerances(o.input));
  }
  print_text(o, paper, iso_own.get());
}

}  // namespace

void register_tolerance(CLI::App& app) {
  auto opts = std::make_shared<ToleranceOptions>();
  CLI::App* sub = app.add_subcommand("tolerance",
                                     "Gear accuracy tolerances (DIN 3961/3962, ISO 1328-1:1995) for one gear at one quality "
                                     "class, in µm, with every intermediate value.");
  sub->add_option("--module", opts->input.module_mm, "Normal module m_n, in mm (ISO 1328-1: 0.5 to 70 mm).")->required();
  sub->add_option("--teeth", opts->input.teeth, "Number of teeth z (an integer, at least 1).")->required();
  sub->add_option("--diameter", opts->input.reference_diameter_mm,
                  "Reference diameter d = z·m_n/cos β, in mm: at least z·m_n (ISO 1328-1: 5 to "
                  "10000 mm).")
      ->required();
  sub->add_option("--quality", opts->input.quality, "Quality class Q (DIN 3961: 1 to 12; ISO 1328-1: 0 to 12). Lower is finer.")
      ->required();
  sub->add_option("--standard", opts->standard,
                  "Which class step and rounding: din (1.4 per class), iso (√2 per class, "
                  "plus ISO's own formulas) or both, side by side. Default: both.")
      ->check(CLI::IsMember({"din", "iso", "both"}));
  CLI::Option* contact = sub->add_option("--contact-ratio", opts->contact_ratio,
                                         "Total contact ratio ε_γ of the mesh, dimensionless (at least 1). Needed only for ISO "
                                         "1328-1 Annex A f_i' and F_i'; without it they are left out, never guessed.");
  sub->add_flag("--json", opts->json,
                "Print JSON instead of a table: every tolerance in µm under keys ending in _um, "
                "plus standard, step_factor, quality and single_flank_error_um (with both "
                "standards: DIN's on top, each standard's object under din3961 and iso1328).");
  sub->footer(
      "Formulas: the paper's eqs (1)-(5) give class-5 values f_f, f_Ha, F_p, F_a and the single "
      "flank error F_i' = 0.8 (F_p + F_a), in µm with m_n and d in mm. A class-Q value is the "
      "class-5 value times the step factor (DIN 1.4^(Q-5), ISO 2^((Q-5)/2)), then rounded once "
      "(ISO: above 10 µm to 1 µm, 5-10 µm to 0.5 µm, below 5 µm to 0.1 µm; DIN: 10 µm and up to "
      "1 µm, below to 0.5 µm). Out-of-range input is an error naming the parameter (module_mm, "
      "teeth, reference_diameter_mm, quality, contact_ratio), never clamped.");
  sub->callback([opts, contact] { run(*opts, contact->count() > 0); });
}

}  // namespace gearsim::app
