// Helpers for pdr_check tests: run the checker, list failed checks, look up results.
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

#include "check/check.hpp"

namespace pdr::check::test {

inline std::set<std::string> failed(const Report& r) {
  std::set<std::string> ids;
  for (const CheckResult& c : r.checks)
    if (c.status == Status::Fail) ids.insert(c.id);
  return ids;
}

inline const CheckResult& result(const Report& r, std::string_view id) {
  const CheckResult* c = r.find(id);
  if (!c) throw std::runtime_error("no result " + std::string(id));
  return *c;
}

inline std::uint64_t count(const Report& r, std::string_view id, const std::string& name) {
  const auto& counts = result(r, id).counts;
  const auto it = counts.find(name);
  return it == counts.end() ? 0 : it->second;
}

inline Report run(const MeshData& m, Options o = {}) { return check_mesh(view_of(m), o); }
inline Report run(const MeshData& m, const Plc& d, Options o = {}) {
  return check_mesh(view_of(m), d, o);
}

// The report as JSON for 1, 2 and 3 checker threads, the thread count itself left out: a
// test that the report does not depend on the threads compares them.
inline std::vector<nlohmann::json> reports_for_threads(const MeshData& m, Options o) {
  std::vector<nlohmann::json> out;
  for (const unsigned threads : {1u, 2u, 3u}) {
    o.threads = threads;
    nlohmann::json j = to_json(run(m, o));
    j["options"].erase("threads");
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace pdr::check::test
