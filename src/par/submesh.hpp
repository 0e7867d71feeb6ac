// Submesh: one of the N pieces of the distributed mesh (paper §4, items 1-2: "M_o has been
// elementwise partitioned into N submeshes ... faces in I_jk are replicated in any
// submeshes that contain them ... each face contains a reference to S_k"), and the
// migration of tets between submeshes that moves the interfaces as the mesh is refined.
//
// A submesh holds its tets in the kernel's TetStore with dense local vertex ids; every
// vertex also has a global id (Gid), the same in every submesh. A face whose other side
// lives in another submesh is closed by a proxy tet (mesh/tet_store.hpp) that names the
// tet across it and where that tet is believed to be (M3 below).
//
// Tets have global ids too, and keep them when they move (a tet is never rebuilt by a
// migration), with an epoch: how many times the tet has moved.
//
// Migration: take() removes a set of tets and returns them as a Migration for submesh
// `to`; give() adds a Migration's tets. Together they keep, over all submeshes and the
// messages in flight:
//   (M1) every tet of the global mesh is in exactly one place, with its orientation and
//        its inside flag;
//   (M2) every face of a tet has, on its other side, a tet of the same submesh or a proxy;
//        a proxy's face is a face of a tet held somewhere else (or on its way here), with
//        opposite orientation;
//   (M3) a proxy names the tet across its face and holds a claim about where that tet is
//        (holder, epoch). Claims about one tet are ordered by epoch, and only a newer
//        claim replaces an older one. When a tet moves, its old submesh sends a relink
//        notice (Relink) with the new claim to the submesh it believes holds each remote
//        neighbour; a submesh that gave that neighbour away at a later move than the
//        claim that brought the notice forwards it there (moved(): every hop follows the
//        neighbour's own moves in time order, so no notice circles), and one that has
//        not seen that move yet keeps the notice until the neighbour arrives. Once every
//        message is delivered, every proxy's claim is the newest, so it names the holder
//        of the tet across its face.
//   (M4) every edge and face of a tet held has the label the mesh gives it (the
//        refinement's labels are the subsegments and subfacets of the surface mesh D, par/
//        refinement_rules.hpp: paper §4 item 2, each submesh starts "with the subsegments
//        and subfacets of its tets"). The caller labels a submesh after extract(); take()
//        sends the labels of the taken tets' edges and faces with them, and give() adds
//        them. A commit (the caller's, after insert()) changes only labels of elements in
//        its cavity, whose tets are all here: it erases those of elements the cavity
//        takes out of the mesh and sets those of elements at the new vertex. An edge or
//        face that leaves the Delaunay tetrahedralization never comes back (points are
//        only added, and the symbolic perturbation decides every tie alike), so a label
//        a submesh keeps of an edge or face it no longer holds is either still right or
//        of one that no tet will have again. A caller must not ask for the label of an
//        edge or face that is not one of a tet it holds.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "delaunay/cavity.hpp"
#include "delaunay/insert.hpp"
#include "geom/point.hpp"
#include "mesh/growing_array.hpp"
#include "mesh/tet_store.hpp"
#include "par/flat_hash_map.hpp"
#include "par/partition.hpp"
#include "par/slot_set.hpp"

namespace pdr::par {

using Gid = std::uint64_t;                      // a vertex's or a tet's global id
using ActorId = std::uint32_t;                  // a submesh
inline constexpr Gid kGhostGid = ~Gid{0};       // the ghost vertex, in every submesh
inline constexpr Gid kNoGid = ~Gid{0} - 1;
inline constexpr ActorId kSameMigration = 0xFFFFFFFFu;  // Side::claim.holder: internal
inline constexpr ActorId kDeleted = 0xFFFFFFFEu;  // moved(): the tet was deleted here
inline constexpr std::uint32_t kNoLabel = 0xFFFFFFFFu;  // an edge or face without a label

// A face by the global ids of its vertices, sorted (orientation is not part of the key).
struct FaceKey {
  std::array<Gid, 3> v{};
  // Three compares, inlined.
  bool operator==(const FaceKey& o) const {
    return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2];
  }
  // Lexicographic, inlined (std::array's <=> is a call per compare where keys are sorted).
  bool operator<(const FaceKey& o) const {
    return v[0] != o.v[0] ? v[0] < o.v[0] : v[1] != o.v[1] ? v[1] < o.v[1] : v[2] < o.v[2];
  }
};
FaceKey face_key(Gid a, Gid b, Gid c);
struct GidHash {  // a mix of all 64 bits (global ids count up in their low bits)
  std::size_t operator()(Gid g) const;
};

// A vertex made in the parallel phase (Submesh::insert): its global id holds the submesh
// that made it and its serial there. Empty for any other global id (M_o's, a tet's).
struct MadeVertex {
  std::size_t maker = 0, serial = 0;
};
inline constexpr Gid kVertexBit = Gid{1} << 39;  // set in a made vertex's global id
inline std::optional<MadeVertex> made_vertex(Gid g) {
  if ((g >> 40) == 0 || (g & kVertexBit) == 0 || g >= kNoGid) return std::nullopt;
  return MadeVertex{static_cast<std::size_t>((g >> 40) - 1),
                    static_cast<std::size_t>(g & (kVertexBit - 1))};
}

// "Tet t is at `holder`, as of its epoch-th move."
struct Claim {
  ActorId holder = 0;
  std::uint32_t epoch = 0;
};

// What a submesh knows of the tet across one of its faces.
struct Side {
  Gid tet = kNoGid;
  Claim claim;
};

struct TetRecord {
  Gid gid = 0;
  std::uint32_t epoch = 0;          // moves so far, this one included
  std::array<Gid, 4> v{};           // positively oriented; a ghost has kGhostGid in slot 3
  std::uint8_t inside = 0;          // bit 0: the tet lies in Ω; bit 1: deferred; bits 2-3:
                                    // whether it is wanted, once known (below)
  std::array<Side, 4> across{};     // per face; claim.holder kSameMigration: in this migration
};

struct VertexRecord {
  Gid gid = 0;
  Point p{};
  std::uint8_t tag = 0;  // Submesh::tag()
};

// A label of an edge or a face (M4), by the global ids of its vertices, sorted.
struct EdgeLabel {
  std::array<Gid, 2> v{};
  std::uint32_t label = kNoLabel;
};
struct FaceLabel {
  std::array<Gid, 3> v{};
  std::uint32_t label = kNoLabel;
};

struct Migration {
  ActorId from = 0, to = 0;
  std::vector<TetRecord> tets;
  std::vector<VertexRecord> vertices;  // every finite vertex of the tets
  std::vector<EdgeLabel> edge_labels;  // of the tets' edges and faces, each once
  std::vector<FaceLabel> face_labels;
};

// For the submesh `recipient`, believed to hold tet `about` (by a claim of epoch
// `about_epoch`): across `face` from it, tet `tet` has moved (claim).
struct Relink {
  ActorId recipient = 0;
  Gid about = kNoGid;
  FaceKey face;
  Gid tet = kNoGid;
  Claim claim;
  std::uint32_t about_epoch = 0;
};

class Submesh {
 public:
  explicit Submesh(ActorId id) : id_(id) {}

  // Submesh k of a partition of (s, pts): its tets (ghosts included), with proxies on the
  // faces towards the other parts. Vertex v of pts gets global id v and tag tags[v] (0
  // when tags is shorter), tet t global id t. `dense`: the tets and vertices of (s, pts)
  // are found by their global ids through vectors as long as the mesh (4 bytes per tet
  // and per vertex of it, whatever the submesh holds: for a rank with few submeshes),
  // else through hash maps of what the submesh holds.
  static Submesh extract(ActorId k, const TetStore& s, std::span<const Point> pts,
                         std::span<const std::uint8_t> inside, const Partition& p,
                         std::span<const std::uint8_t> tags = {}, bool dense = false);

  ActorId id() const { return id_; }
  const TetStore& store() const { return store_; }
  std::span<const Point> points() const { return points_; }
  Gid gid(VertexId v) const { return v == kGhostVertex ? kGhostGid : gids_[v]; }
  // A byte per vertex that the submesh does not read: given to M_o's vertices by
  // extract(), it travels with the vertex; a vertex made by insert() gets the tag given
  // there (the refinement: where the vertex lies on ∂Ω, so that most edges and faces are
  // known to be no element of D without a lookup, par/refinement_rules.hpp). 0 for the
  // ghost.
  std::uint8_t tag(VertexId v) const { return v < tags_.size() ? tags_[v] : 0; }
  Gid tet_gid(TetId t) const { return slot_[t].gid; }
  // The real tet with global id g, or kNoTet when it is not here.
  TetId find_tet(Gid g) const;
  // The same, tried first at slot `hint` (where g was seen before: a queued tet's slot),
  // which saves the index's lookup while the tet has not moved.
  TetId find_tet(Gid g, TetId hint) const {
    if (hint < slot_.size() && slot_[hint].gid == g && g != kNoGid && store_.is_alive(hint))
      return hint;
    return find_tet(g);
  }
  bool inside(TetId t) const { return t < slot_.size() && (slot_[t].inside & 1) != 0; }
  // Refinement: the step of real tet t was deferred (par/refinement_rules.hpp); the mark
  // travels with the tet, so no rank takes that step up again in the parallel phase.
  bool deferred(TetId t) const { return t < slot_.size() && (slot_[t].inside & 2) != 0; }
  void mark_deferred(TetId t) { slot_[t].inside |= 2; }
  // The refinement's verdict on real tet t (StepRules::wants), once computed: a fixed
  // property of the tet, so it travels with it and is not computed again on arrival.
  std::optional<bool> wanted(TetId t) const {
    if (t >= slot_.size() || (slot_[t].inside & 4) == 0) return std::nullopt;
    return (slot_[t].inside & 8) != 0;
  }
  void set_wanted(TetId t, bool w) {
    slot_[t].inside = static_cast<std::uint8_t>((slot_[t].inside & ~8) | 4 | (w ? 8 : 0));
  }
  // Sets the inside flag of real tet t (a tet insert() just made: the refinement's flags
  // of a cavity that crosses ∂Ω).
  void set_inside(TetId t, bool in) {
    slot_[t].inside = static_cast<std::uint8_t>((slot_[t].inside & ~1) | (in ? 1 : 0));
  }
  // M4: the label of edge {a, b} and of face {a, b, c} (local vertices), or kNoLabel.
  std::uint32_t edge_label(VertexId a, VertexId b) const;
  std::uint32_t face_label(VertexId a, VertexId b, VertexId c) const;
  // Sets a label (not kNoLabel; the ghost vertex has none), or erases one.
  void set_edge_label(VertexId a, VertexId b, std::uint32_t label);
  void set_face_label(VertexId a, VertexId b, VertexId c, std::uint32_t label);
  void erase_edge_label(VertexId a, VertexId b);
  void erase_face_label(VertexId a, VertexId b, VertexId c);
  std::size_t labels() const { return label_count_; }
  // The local vertex with global id g, or kNoVertex when it is not here.
  VertexId find_vertex(Gid g) const;

  // What a proxy knows of the tet across it (precondition: t is a live proxy).
  const Side& proxy_side(TetId t) const;
  std::size_t real_tets() const { return store_.live() - proxies_; }
  std::size_t proxies() const { return proxies_; }
  std::size_t waiting_relinks() const;

  // Removes `tets` (live, not proxies, no repeats) for submesh `to` (not this one).
  // Kept tets glued to them get proxies; proxies glued to them are dropped, and `relinks`
  // gets the notices for the submeshes those proxies name.
  Migration take(std::span<const TetId> tets, ActorId to, std::vector<Relink>& relinks);
  // Adds a migration's tets (m.to == id()); returns their local ids, in m.tets's order.
  std::vector<TetId> give(const Migration& m);

  // Bowyer-Watson at this submesh: commits cavity c, built on this store as it is now and
  // complete (conflict tets and ring all real tets here: par/cavity_search.hpp), with
  // c.point as a new vertex. The vertex and the new tets get fresh global ids (this
  // submesh's id and a serial); the new tets get `inside`, the vertex `tag`. The deleted
  // tets that another submesh may name are recorded (moved() says kDeleted), so a late
  // request or notice about one is answered. Returns the new vertex; `created()` lists the
  // new tets.
  VertexId insert(const Cavity& c, std::uint8_t inside, std::uint8_t tag = 0);
  std::span<const TetId> created() const { return committer_.created(); }

  // Applies a relink notice addressed here; false when it must go on to the submesh this
  // one sent r.about to: then r.recipient and r.about_epoch name that hand-over.
  bool relink(Relink& r);
  // Where this submesh sent tet g at a move later than the claim of epoch `after` that
  // points here; nullopt when there is none: g is here, or on its way here. Following
  // these records only ever goes to later moves, so it ends at g's holder.
  std::optional<Claim> moved(Gid g, std::uint32_t after) const;

  // M2 here: the store's topology, each proxy found from the tet it closes.
  std::vector<std::string> check() const;

 private:
  // Adds the vertex if new (p given, with its tag).
  VertexId local_vertex(Gid g, const Point* p, std::uint8_t tag = 0);
  FaceKey key_of(TetId t, int f) const;
  // The proxy glued to the face of real tet t with key k, or kNoTet. A proxy is found
  // from the tet it closes, not through an index of faces: the face of a tet that a
  // migration brings (or that a relink notice names) is that of a tet known by its
  // global id, and (M2, M3) a proxy names the very tet across its face, since no commit
  // makes a tet next to a proxy (a cavity and its ring are all real tets here).
  TetId proxy_on(TetId t, const FaceKey& k) const;
  TetId add_proxy(TetId t, int f, const Side& side);  // glued to face f of real tet t
  void drop_proxy(TetId proxy);
  void claim(TetId proxy, const Claim& c);  // keeps the newer claim
  void record_tet(TetId t, Gid g, std::uint32_t epoch, std::uint8_t inside);

  // Fresh global ids: (id + 1) * 2^40 + serial for a tet, with 2^39 added and a serial of
  // their own for a vertex; M_o's are below 2^40.
  Gid fresh_gid() { return (Gid{id_} + 1) << 40 | serial_++; }
  Gid fresh_vertex_gid() { return (Gid{id_} + 1) << 40 | kVertexBit | vertex_serial_++; }
  // Where the local id of vertex g is kept (kNoVertex there: not here yet).
  VertexId* vertex_slot(Gid g);

  ActorId id_;
  Gid serial_ = 0, vertex_serial_ = 0;
  CavityCommitter committer_;
  TetStore store_;
  GrowingArray<Point> points_;
  GrowingArray<Gid> gids_;
  std::vector<std::uint8_t> tags_;
  // Local vertex ids by global id; with a dense index (extract()), M_o's in a vector and
  // those made in the phase in a vector per submesh that made them, by serial.
  bool dense_ = false;
  std::vector<VertexId> m0_local_;
  std::vector<std::vector<VertexId>> fresh_local_;
  std::unordered_map<Gid, VertexId> local_;
  // Per slot, together (a tet's step reads most of them at once): its global id, epoch,
  // flags (inside, deferred, wanted: TetRecord::inside), and whether another submesh may
  // name this tet (it was glued to a proxy, or arrived by migration: only such a tet's
  // deletion is recorded, since no message can name the others, which are most tets a
  // commit deletes).
  struct SlotInfo {
    Gid gid = kNoGid;
    std::uint32_t epoch = 0;
    std::uint8_t inside = 0;
    std::uint8_t exposed = 0;
  };
  GrowingArray<SlotInfo> slot_;
  // Real tets by global id: those made here by slot_of_serial_[serial], with a dense
  // index M_o's by m0_slot_[gid], each checked against slot_'s gid (a slot freed or reused no
  // longer matches, so nothing is erased: the hot paths touch no hash map); the others in
  // tet_at_, which holds only the tets here.
  GrowingArray<TetId> slot_of_serial_;
  std::vector<TetId> m0_slot_;
  FlatHashMap<Gid, TetId, GidHash> tet_at_;
  bool made_here(Gid g) const { return g >> 40 == Gid{id_} + 1; }
  void index_tet(Gid g, TetId t);
  void unindex_tet(Gid g);
  // The live proxies' sides, by slot: a few per cent of the slots, so not an array
  // along the store (16 bytes a slot, faulted in for nothing on most).
  FlatHashMap<TetId, Side, SlotHash> side_;
  std::size_t proxies_ = 0;  // live proxies
  // take(): the tets it takes, and the vertices it has listed (ids too: SlotSet holds any
  // 32-bit id).
  SlotSet taken_, seen_;
  std::vector<std::pair<TetId, int>> keep_faces_;  // take()'s buffers, kept for the next
  std::vector<Side> keep_sides_;
  std::vector<TetId> drop_;
  std::vector<std::pair<FaceKey, HalfFace>> internal_;  // give()'s buffer, kept for the next
  // Tets given away: the latest hand-over; deleted tets another submesh may name. A record
  // stays when its tet comes back (erasing it would cost a probe per arriving tet): it is
  // read only for a tet that is not here, and the tet's next departure or deletion here
  // overwrites it first.
  FlatHashMap<Gid, Claim, GidHash> moved_;
  std::unordered_map<Gid, std::vector<Relink>> waiting_;  // notices about tets on their way
  // M4: labels by the sorted local ids of their vertices, listed at the smallest of them
  // (a vertex on ∂Ω starts a few edges and faces of D; most vertices start none, and the
  // lookups of their edges and faces end at one look).
  struct EdgeEntry {
    VertexId b;
    std::uint32_t label;
  };
  struct FaceEntry {
    VertexId b, c;
    std::uint32_t label;
  };
  struct VertexLabels {
    std::vector<EdgeEntry> edges;
    std::vector<FaceEntry> faces;
  };
  static constexpr std::uint32_t kNoList = 0xFFFFFFFFu;
  std::vector<std::uint32_t> label_list_;  // per vertex: its index in lists_, or kNoList
  std::vector<VertexLabels> lists_;
  std::size_t label_count_ = 0;
  const VertexLabels* list_at(VertexId v) const {
    return v < label_list_.size() && label_list_[v] != kNoList ? &lists_[label_list_[v]] : nullptr;
  }
  VertexLabels& list_for(VertexId v);
  void collect_labels(std::span<const TetId> tets, Migration& m) const;
};

}  // namespace pdr::par
