// check_mesh: runs every checker over one shared, read-only Context; the report lists them in one order.
//
// Order and gating: validity.indices and validity.coordinates come first; if either fails,
// every other check is Skipped (indices and finite coordinates are preconditions of all
// geometry). Then orientation (its exact signs are shared), the topology and the vertex
// grid; then three groups that share only what is already computed, concurrently with
// several threads: the remaining validity checks, Delaunay emptiness and quality, and with
// a domain the conformity and encroachment checks (without one those are Skipped). Last,
// delaunay.empty_sphere runs again querying every tet if its Delaunay-lemma verdict rested
// on validity.overlap and that failed. The report lists the checks in one fixed order
// whatever the threads.
#include <algorithm>
#include <chrono>
#include <future>
#include <utility>

#include "check/checks.hpp"

namespace pdr::check {
namespace {

struct Entry {
  std::string_view id, invariant;
};

constexpr Entry kChecks[] = {
    {"validity.indices", "§1.1 T(Omega) is a mesh of tetrahedra: vertex indices in range"},
    {"validity.coordinates", "points are finite doubles (exact rationals)"},
    {"validity.orientation", "§1.1 tetrahedra: orient3d(a,b,c,d) > 0 (positive volume)"},
    {"validity.duplicate_vertices", "§1.1 mesh vertices are distinct points"},
    {"validity.unreferenced_vertices", "every vertex belongs to a tet (warning only)"},
    {"validity.face_sharing", "§1.2 a face is shared by at most two tets, on opposite sides"},
    {"validity.boundary_closed", "the boundary faces form a closed, consistently oriented surface"},
    {"validity.faces", "listed faces are the boundary faces (plus interior facet faces)"},
    {"validity.overlap", "§1.1 T(Omega) is a tetrahedralization: tets meet only in common faces"},
    {"delaunay.empty_sphere", "§1.2 Delaunay: no vertex strictly inside a tet's circumsphere"},
    {"quality.ratio", "Theorem 1 (2): radius-edge ratio R/lmin < B for every tet"},
    {"quality.shortest_edge", "Theorem 1 (1): every edge is longer than h"},
    {"conformity.vertices", "§2.1 (1): every input vertex is a mesh vertex"},
    {"conformity.segments", "§1.1, §2.1 (1): every segment is a union of subsegments (mesh edges)"},
    {"conformity.facets", "§1.1, §2.1 (1): every facet is a union of subfacets (mesh faces)"},
    {"conformity.volume", "§1.1 T(Omega) fills Omega: boundary faces in facets, holes empty, regions filled"},
    {"encroachment.subsegments", "§1.1, Lemma 1 (1): no vertex strictly inside a subsegment's diametral sphere"},
    {"encroachment.subfacets", "§1.1, Lemma 1 (1): no vertex strictly inside a subfacet's equatorial sphere"},
};

void skip_rest(Report& rep, const std::string& reason) {
  for (const Entry& e : kChecks) {
    if (rep.find(e.id)) continue;
    CheckResult r = make_result(e.id);
    r.reason = reason;
    rep.checks.push_back(std::move(r));
  }
}

// Checks run one after another, their results and times kept for the report; `on_phase`
// (Options::on_phase, or null) hears of each phase as it starts.
class Group {
 public:
  explicit Group(const std::function<void(std::string_view)>* on_phase) : on_phase_(on_phase) {}
  template <class F>
  auto time(const char* phase, F&& f) {
    if (on_phase_ && *on_phase_) (*on_phase_)(phase);
    const auto t0 = std::chrono::steady_clock::now();
    auto result = f();
    seconds_.emplace_back(phase, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return result;
  }
  template <class F>
  void add(const char* phase, F&& f) {
    results_.push_back(time(phase, std::forward<F>(f)));
  }
  CheckResult* find(std::string_view id) {
    for (CheckResult& r : results_)
      if (r.id == id) return &r;
    return nullptr;
  }
  void report_into(Report& rep) {
    for (CheckResult& r : results_) rep.checks.push_back(std::move(r));
    for (const auto& [phase, s] : seconds_) rep.seconds[phase] += s;
    results_.clear();
    seconds_.clear();
  }

 private:
  const std::function<void(std::string_view)>* on_phase_;
  std::vector<CheckResult> results_;
  std::vector<std::pair<const char*, double>> seconds_;
};

Report run(const MeshView& mesh, const Plc* domain, Options o) {
  o.threads = std::max(1u, o.threads);
  Report rep;
  rep.points = mesh.points.size();
  rep.tets = mesh.tets.size();
  rep.has_domain = domain != nullptr;
  rep.options = o;
  rep.checks.push_back(check_indices(mesh, o));
  rep.checks.push_back(check_coordinates(mesh, o));
  if (!rep.ok()) {
    skip_rest(rep, "not run: validity.indices or validity.coordinates failed");
    return rep;
  }
  Context c;
  c.mesh = mesh;
  c.domain = domain;
  c.options = o;
  Group front(&o.on_phase);
  front.add("orientation", [&] { return check_orientation(mesh, o, c.orientation); });
  c.topology = front.time("topology", [&] { return build_topology(mesh.tets, o.threads); });
  rep.boundary_faces = c.topology.boundary.size();
  c.grid = front.time("grid", [&] { return PointGrid(mesh.points); });
  // Three groups that read the context and nothing the others write: the validity of the
  // tetrahedralization, the domain's (map, conformity, encroachment), and the Delaunay and
  // quality checks (delaunay.empty_sphere fills circum_r2 for quality.ratio). The first two
  // are mostly single-threaded, so with several threads they run on threads of their own
  // beside the third instead of leaving cores idle (and then say nothing of their progress);
  // with one, on the caller's when asked for. The report lists the results in kChecks'
  // order either way.
  const bool concurrent = o.threads > 1;
  const auto policy = concurrent ? std::launch::async : std::launch::deferred;
  const auto* const progress = concurrent ? nullptr : &o.on_phase;
  auto validity = std::async(policy, [&] {
    Group g(progress);
    g.add("validity", [&] { return check_duplicate_vertices(c); });
    g.add("validity", [&] { return check_unreferenced_vertices(c); });
    g.add("validity", [&] { return check_face_sharing(c); });
    g.add("validity", [&] { return check_boundary_closed(c); });
    g.add("validity", [&] { return check_listed_faces(c); });
    g.add("overlap", [&] { return check_overlap(c); });
    return g;
  });
  auto conforming = std::async(domain ? policy : std::launch::deferred, [&] {
    Group g(progress);
    if (!domain) return g;
    c.domain_map = g.time("domain", [&] { return map_domain(*domain, mesh, c.topology, c.grid, o); });
    g.add("conformity", [&] { return check_input_vertices(c); });
    g.add("conformity", [&] { return check_segments(c); });
    g.add("conformity", [&] { return check_facets(c); });
    g.add("conformity", [&] { return check_domain_volume(c); });
    g.add("encroachment", [&] { return check_subsegments_unencroached(c); });
    g.add("encroachment", [&] { return check_subfacets_unencroached(c); });
    return g;
  });
  Group geometry(&o.on_phase);
  // (Without the overlap check the lemma could not be trusted: every tet is searched.)
  geometry.add("delaunay", [&] { return check_empty_circumspheres(c, o.check_overlap); });
  geometry.add("quality", [&] { return check_radius_edge_ratio(c); });
  geometry.add("quality", [&] { return check_shortest_edge(c); });
  Group checked_validity = validity.get(), checked_domain = conforming.get();
  // The Delaunay lemma's verdict assumes disjoint interiors (delaunay_empty.cpp): where
  // they are not, every tet is queried.
  const CheckResult* overlap = checked_validity.find("validity.overlap");
  if (CheckResult* empty = geometry.find("delaunay.empty_sphere");
      empty && used_lemma(*empty) && !(overlap && overlap->status == Status::Pass))
    *empty = geometry.time("delaunay", [&] { return check_empty_circumspheres(c, false); });
  for (Group* g : {&front, &checked_validity, &geometry, &checked_domain}) g->report_into(rep);
  rep.on_sphere_complete = !c.on_sphere.empty() && !c.on_sphere_overflow;
  if (rep.on_sphere_complete) {
    std::size_t on_sphere = 0;
    for (const auto& part : c.on_sphere) on_sphere += part.size();
    rep.on_sphere.reserve(on_sphere);
    for (const auto& part : c.on_sphere) rep.on_sphere.insert(rep.on_sphere.end(), part.begin(), part.end());
    std::sort(rep.on_sphere.begin(), rep.on_sphere.end());
  }
  if (!domain) skip_rest(rep, "no domain given");
  return rep;
}

}  // namespace

const std::vector<std::string_view>& check_ids() {
  static const std::vector<std::string_view> ids = [] {
    std::vector<std::string_view> v;
    for (const Entry& e : kChecks) v.push_back(e.id);
    return v;
  }();
  return ids;
}

CheckResult make_result(std::string_view id) {
  CheckResult r;
  r.id = std::string(id);
  for (const Entry& e : kChecks)
    if (e.id == id) r.invariant = std::string(e.invariant);
  return r;
}

void conclude(CheckResult& r) { r.status = r.violations == 0 ? Status::Pass : Status::Fail; }

Finding make_finding(const MeshView& mesh, std::string kind, std::uint64_t id,
                     std::vector<std::uint32_t> vs, std::string message) {
  Finding f;
  f.kind = std::move(kind);
  f.id = id;
  for (std::uint32_t v : vs)
    if (v < mesh.points.size()) f.points.push_back(mesh.points[v]);
  f.vertices = std::move(vs);
  f.message = std::move(message);
  return f;
}

Finding tet_finding(const MeshView& mesh, std::uint64_t t, std::string message) {
  const Tet& k = mesh.tets[t];
  return make_finding(mesh, "tet", t, {k[0], k[1], k[2], k[3]}, std::move(message));
}

MeshView view_of(const MeshData& mesh) { return {mesh.points, mesh.tets, mesh.faces}; }

bool Report::ok() const {
  for (const CheckResult& r : checks)
    if (r.status == Status::Fail) return false;
  return true;
}

const CheckResult* Report::find(std::string_view id) const {
  for (const CheckResult& r : checks)
    if (r.id == id) return &r;
  return nullptr;
}

Report check_mesh(const MeshView& mesh, Options options) { return run(mesh, nullptr, options); }

Report check_mesh(const MeshView& mesh, const Plc& domain, Options options) {
  return run(mesh, &domain, options);
}

Report check_arrays(std::span<const double> xyz, std::span<const std::uint32_t> tets,
                    std::span<const std::uint32_t> faces, const Plc* domain, Options options) {
  MeshData m;
  m.points.resize(xyz.size() / 3);
  for (std::size_t i = 0; i < m.points.size(); ++i) m.points[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  m.tets.resize(tets.size() / 4);
  for (std::size_t i = 0; i < m.tets.size(); ++i)
    m.tets[i] = {tets[4 * i], tets[4 * i + 1], tets[4 * i + 2], tets[4 * i + 3]};
  m.faces.resize(faces.size() / 3);
  for (std::size_t i = 0; i < m.faces.size(); ++i)
    m.faces[i] = {faces[3 * i], faces[3 * i + 1], faces[3 * i + 2]};
  return run(view_of(m), domain, options);
}

}  // namespace pdr::check
