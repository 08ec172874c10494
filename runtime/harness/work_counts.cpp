// Work counts of an instrumented run (work_counts.h).
#include "runtime/harness/work_counts.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace shadowc::rt {

std::optional<uint64_t> WorkCounts::total(const std::string& field) const {
  const auto it = std::find(fields.begin(), fields.end(), field);
  if (it == fields.end()) return std::nullopt;
  return totals[size_t(it - fields.begin())];
}

uint64_t WorkCounts::receivers() const { return total("receivers").value_or(0); }

double WorkCounts::perReceiver(const std::string& field) const {
  const uint64_t n = receivers();
  return n == 0 ? 0.0 : double(total(field).value_or(0)) / double(n);
}

const BufferDesc* workCounterBuffer(const Manifest& manifest) {
  for (const BufferDesc& b : manifest.buffers)
    if (!b.fields.empty()) return &b;
  return nullptr;
}

WorkCounts workCountsFromWords(const Manifest& manifest, const std::vector<int32_t>& words) {
  const BufferDesc* buffer = workCounterBuffer(manifest);
  if (!buffer) throw std::invalid_argument("work counts: the manifest has no counter buffer");
  if (buffer->components != 2 || words.size() < 2 * buffer->fields.size())
    throw std::invalid_argument(fmt::format("work counts: buffer '{}' holds {} words for {} fields", buffer->name,
                                            words.size(), buffer->fields.size()));
  WorkCounts w;
  for (const Pass& p : manifest.passes)
    for (const Binding& b : p.bindings)
      if (b.image == buffer->name && b.access == Access::StorageBufferReadWrite) w.pass = p.name;
  w.fields = buffer->fields;
  for (size_t k = 0; k < w.fields.size(); ++k)
    w.totals.push_back(uint64_t(uint32_t(words[2 * k])) | uint64_t(uint32_t(words[2 * k + 1])) << 32);
  return w;
}

std::string workFields(const WorkCounts& work) {
  std::string out;
  for (size_t k = 0; k < work.fields.size(); ++k) {
    if (work.fields[k] == "receivers" || work.totals[k] == 0) continue;
    out += fmt::format("{}{}={:.6g}", out.empty() ? "" : ";", work.fields[k], work.perReceiver(work.fields[k]));
  }
  return out;
}

nlohmann::ordered_json workJson(const WorkCounts& work) {
  nlohmann::ordered_json j;
  j["pass"] = work.pass;
  j["receivers"] = work.receivers();
  j["fields"] = work.fields;  // the buffer's order, which a reader's unordered object would lose
  // Built apart and moved in: an ordered_json object is a vector, so a reference to one member
  // would dangle once the next is added.
  nlohmann::ordered_json totals = nlohmann::ordered_json::object(), per = nlohmann::ordered_json::object();
  for (size_t k = 0; k < work.fields.size(); ++k) {
    totals[work.fields[k]] = work.totals[k];
    if (work.fields[k] != "receivers") per[work.fields[k]] = work.perReceiver(work.fields[k]);
  }
  j["totals"] = std::move(totals);
  j["per_receiver"] = std::move(per);
  return j;
}

WorkCounts workFromJson(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("totals") || !j["totals"].is_object() || !j.contains("pass") ||
      !j["pass"].is_string())
    throw std::invalid_argument("work counts: expected an object with \"pass\" and \"totals\"");
  WorkCounts w;
  w.pass = j["pass"].get<std::string>();
  std::vector<std::string> order;
  if (j.contains("fields") && j["fields"].is_array()) {
    for (const auto& f : j["fields"])
      if (f.is_string()) order.push_back(f.get<std::string>());
  } else {
    for (const auto& [field, total] : j["totals"].items()) order.push_back(field);
  }
  for (const std::string& field : order) {
    const auto it = j["totals"].find(field);
    if (it == j["totals"].end() || !it->is_number_unsigned())
      throw std::invalid_argument("work counts: total '" + field + "' is missing or not a count");
    w.fields.push_back(field);
    w.totals.push_back(it->get<uint64_t>());
  }
  if (w.fields.size() != j["totals"].size())
    throw std::invalid_argument("work counts: \"fields\" does not name every total");
  return w;
}

}  // namespace shadowc::rt
