#include "app/tolerance_report.hpp"

#include <iomanip>
#include <sstream>

#include "core/errors.hpp"

namespace gearsim::app {

std::string pad(const std::string& s, std::size_t width, bool right) {
  std::size_t cols = 0;
  for (unsigned char ch : s) cols += (ch & 0xC0) != 0x80;
  const std::string fill(cols < width ? width - cols : 0, ' ');
  return right ? fill + s : s + fill;
}

std::string fixed(double v, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << v;
  return out.str();
}

void print_tolerance_grading(std::ostream& out, const ToleranceResult& r) {
  out << "  " << standard_key(r.standard) << " = " << standard_name(r.standard) << ", class " << r.quality << ": step factor "
      << step_rule(r.standard) << " = " << fixed(r.step_factor, 4) << "\n            rounding: " << rounding_rule(r.standard) << "\n";
}

void print_tolerance_table(std::ostream& out, const std::vector<ToleranceResult>& results) {
  const ToleranceResult& first = results.front();
  out << "  " << pad("symbol", 7) << pad("deviation", 45) << pad("class 5", 10, true);
  for (const ToleranceResult& r : results) {
    const std::string tag = std::string(standard_key(r.standard)) + " x" + fixed(r.step_factor, 3);
    out << "  " << pad(tag, 16, true) << pad("rounded", 9, true);
  }
  out << "   class-5 formula (m, d in mm)\n";
  for (std::size_t i = 0; i < first.components.size(); ++i) {
    const ToleranceComponent& c = first.components[i];
    out << "  " << pad(c.symbol, 7) << pad(c.name, 45) << pad(fixed(c.class5_um, 3), 10, true);
    for (const ToleranceResult& r : results) {
      const ToleranceComponent& rc = r.components[i];
      out << "  " << pad(fixed(rc.unrounded_um, 3), 16, true) << pad(fixed(rc.value_um, 1), 9, true);
    }
    out << "   " << c.formula << "\n";
  }
  out << "  (all values in µm)\n";
}

json tolerance_result_json(const ToleranceResult& r) {
  json j;
  j["standard"] = standard_key(r.standard);
  j["standard_name"] = standard_name(r.standard);
  j["formula_set"] = r.formula_set;
  j["quality"] = r.quality;
  j["step_factor"] = r.step_factor;
  j["step_rule"] = step_rule(r.standard);
  j["rounding_rule"] = rounding_rule(r.standard);
  j["single_flank_error_um"] = r.single_flank_error_um ? json(*r.single_flank_error_um) : json(nullptr);
  if (r.composite_k) j["composite_k"] = *r.composite_k;
  json components = json::array();
  for (const ToleranceComponent& c : r.components) {
    j[c.key + "_um"] = c.value_um;
    components.push_back({{"key", c.key},
                          {"symbol", c.symbol},
                          {"name", c.name},
                          {"formula", c.formula},
                          {"class5_um", c.class5_um},
                          {"unrounded_um", c.unrounded_um},
                          {"value_um", c.value_um}});
  }
  j["components"] = components;
  return j;
}

namespace {

json input_json(const ToleranceInput& in) {
  return {{"module_mm", in.module_mm},
          {"teeth", in.teeth},
          {"reference_diameter_mm", in.reference_diameter_mm},
          {"quality", in.quality},
          {"contact_ratio", in.contact_ratio ? json(*in.contact_ratio) : json(nullptr)}};
}

}  // namespace

json tolerance_json(const ToleranceInput& input, const std::string& standard) {
  if (standard != "din" && standard != "iso" && standard != "both")
    throw InputError("standard: '" + standard + "' is none of din, iso, both");
  const bool din = standard != "iso";
  const bool iso = standard != "din";
  std::vector<ToleranceResult> paper;
  if (din) paper.push_back(paper_tolerances(input, ToleranceStandard::Din3961));
  if (iso) paper.push_back(paper_tolerances(input, ToleranceStandard::Iso1328));
  // Single standard: that standard's object. Both: the paper's DIN answer on top (the paper
  // uses DIN), each standard's object under its key.
  json iso_json;
  if (iso) {
    iso_json = tolerance_result_json(paper.back());
    iso_json["iso1328_formulas"] = tolerance_result_json(iso1328_tolerances(input));
  }
  json out;
  if (din && iso) {
    const ToleranceResult& d = paper.front();
    out["single_flank_error_um"] = *d.single_flank_error_um;
    out["standard"] = standard_key(d.standard);
    out["step_factor"] = d.step_factor;
    out["quality"] = d.quality;
    out["din3961"] = tolerance_result_json(d);
    out["iso1328"] = iso_json;
  } else {
    out = din ? tolerance_result_json(paper.front()) : iso_json;
  }
  out["input"] = input_json(input);
  return out;
}

}  // namespace gearsim::app
