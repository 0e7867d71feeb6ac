// InsertionActor: the event loop and the protocol's handlers (par/insertion_actor.hpp).
#include "par/insertion_actor.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>

#include "delaunay/spatial_sort.hpp"

namespace pdr::par {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

enum class Type : std::uint8_t { Fetch = 1, Tets = 2, Refuse = 3, Relink = 4, Point = 5, Reject = 6 };

Bytes migration_message(std::uint64_t search, bool walk, const Migration& m) {
  WireWriter w;
  w.put(Type::Tets).put(search).put<std::uint8_t>(walk).put(m.from).put(m.to);
  w.put_vector(m.tets).put_vector(m.vertices).put_vector(m.edge_labels).put_vector(m.face_labels);
  return w.take();
}

}  // namespace

InsertionStats& operator+=(InsertionStats& a, const InsertionStats& b) {
  a.commits += b.commits, a.rounds += b.rounds, a.setbacks += b.setbacks;
  a.duplicates += b.duplicates, a.fetches_served += b.fetches_served, a.refused += b.refused;
  a.tets_sent += b.tets_sent, a.points_passed += b.points_passed, a.deferred += b.deferred;
  a.fetches_rejected += b.fetches_rejected;
  a.gone += b.gone, a.deferred_early += b.deferred_early;
  a.local_while_waiting += b.local_while_waiting, a.splits += b.splits;
  a.facet_points += b.facet_points;
  a.completed_local_s += b.completed_local_s;
  a.completed_distributed_s += b.completed_distributed_s;
  a.masked_local_s += b.masked_local_s, a.masked_distributed_s += b.masked_distributed_s;
  a.setback_s += b.setback_s, a.served_s += b.served_s, a.other_s += b.other_s;
  a.poll_s += b.poll_s, a.poll_excess_s += b.poll_excess_s;
  return a;
}

InsertionActor::InsertionActor(Transport& t, Submesh sub, std::uint64_t seed, StepRules* rules)
    : t_(t),
      sub_(std::move(sub)),
      td_(t),
      rng_(seed ^ (0x9E3779B97F4A7C15ull * (sub_.id() + 1))),
      rules_(rules) {}

void InsertionActor::add_wanted_tets() {
  const TetStore& st = sub_.store();
  for (TetId t = 0; t < st.slots(); ++t)
    if (st.is_alive(t) && !st.is_proxy(t)) want(t);
  // Along a Hilbert curve (hilbert_tet_order): in M_o's slot order, which its own
  // refinement scattered over space, the phase took 1.2 times as long on 2 ranks and 1.3
  // times on one (docs/parallel.md).
  const std::vector<std::uint32_t> order = hilbert_tet_order(st, sub_.points(), tets_);
  GrowingArray<TetId> sorted(tets_.size());
  for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = tets_[order[i]];
  tets_ = std::move(sorted);
  tets_head_ = 0;
}

void InsertionActor::want(TetId t) {
  if (rules_ == nullptr || !may_step(t)) return;
  std::optional<bool> w = sub_.wanted(t);
  if (!w) sub_.set_wanted(t, *(w = rules_->wants(sub_, t)));
  if (*w) tets_.push_back(t);
}

bool InsertionActor::next_ready(Waiting& w, int& skips, bool remote) {
  if (!ready_.empty()) {
    w = ready_.front();
    ready_.pop_front();
    return true;
  }
  if (remote && !remote_.empty()) {
    w = remote_.front();
    remote_.pop_front();
    return true;
  }
  const TetStore& st = sub_.store();
  while (tets_head_ < tets_.size() && skips > 0) {
    const TetId t = tets_[tets_head_++];
    if (tets_head_ > 4096 && tets_head_ * 2 > tets_.size()) {
      tets_.erase(tets_.begin(), tets_.begin() + static_cast<std::ptrdiff_t>(tets_head_));
      tets_head_ = 0;
    }
    if (t < st.slots() && st.is_alive(t) && !st.is_proxy(t) && may_step(t) &&
        sub_.wanted(t) == std::optional<bool>(true)) {
      w = Waiting{Point{}, sub_.tet_gid(t)};
      w.slot = t;
      return true;
    }
    ++stats_.gone;
    --skips;
  }
  return false;
}

void InsertionActor::send(int to, Bytes b) { t_.send(to, std::move(b)); }

bool InsertionActor::step(Clock::time_point& now) {
  ++tick_;
  // Table 1's clocks: a message's handling is charged by its kind (a reply to this rank's
  // search to the search; a request served while that search waits is masked); the rest
  // of the poll is polling.
  double handled = 0;
  const Clock::time_point p0 = now;
  const std::size_t got = t_.poll(
      [&](int from, std::span<const std::byte> m) {
        const bool waiting_now = waiting();
        const auto kind = m.empty() ? Type{} : static_cast<Type>(std::to_integer<std::uint8_t>(m[0]));
        const bool reply = kind == Type::Tets || kind == Type::Refuse || kind == Type::Reject;
        const auto h0 = Clock::now();
        receive(from, m);
        const double d = since(h0);
        handled += d;
        if (reply)
          charge_search(d);
        else if (waiting_now)
          stats_.masked_distributed_s += d;
        else
          stats_.served_s += d;
      },
      16);
  worked_ = got > 0;
  const auto w0 = Clock::now();  // the poll's end, and the work's start
  now = w0;
  // The work's seconds, from one reading at its end (the step's last: `now`).
  const auto work_s = [&] {
    now = Clock::now();
    return std::chrono::duration<double>(now - w0).count();
  };
  const double polling = std::chrono::duration<double>(w0 - p0).count() - handled;
  stats_.poll_s += polling;
  if (got == 0 && !idle() && !waiting()) stats_.poll_excess_s += polling;
  for (std::size_t i = 0; i < delayed_.size();)
    if (delayed_[i].wake <= tick_) {
      ready().push_back(delayed_[i]);
      delayed_[i] = delayed_.back();
      delayed_.pop_back();
    } else {
      ++i;
    }
  // Queued tets that have left by their turn (most of a commit's new bad tets: a later
  // commit or a migration took them) are dropped in the same step, up to kDropsPerStep,
  // without a poll and a clock reading for each.
  constexpr int kDropsPerStep = 64;
  if (active_ && again_) {
    again_ = false;
    round();
    worked_ = true;
    charge_search(work_s());
  } else if (!active_ && has_ready()) {
    worked_ = true;
    int skips = kDropsPerStep;
    for (Waiting w; next_ready(w, skips, true);) {
      if (start(w)) break;
      ++stats_.gone;
      if (--skips <= 0) break;
    }
    if (active_ || end_ != End::None)
      charge_search(work_s());
    else
      stats_.other_s += work_s();  // tets gone, a point passed on
  } else if (active_ && !again_ && has_local()) {  // waiting for replies: local steps
    worked_ = true;
    int skips = kDropsPerStep;
    for (Waiting w; next_ready(w, skips, false);) {
      const Local r = local_step(w);
      if (r == Local::Done) break;
      if (r == Local::Skipped) continue;  // ready_ is shorter by one: the loop ends
      ++stats_.gone;
      if (--skips <= 0) break;
    }
    stats_.masked_local_s += work_s();
  }
  if (worked_) td_.activity();
  return td_.step(idle());
}

InsertionActor::Local InsertionActor::local_step(const Waiting& w) {
  // A step that needed other ranks before (set back since: trying it again at a wait
  // would rebuild its cavity for nothing) or a given point (a search from any tet here):
  // put aside for a search of its own, its tet not looked up (whether it has left is seen
  // when it starts). Once there, no later wait goes over it.
  if (w.parked || (w.tet == kNoGid && w.a == kNoGid)) {
    room(remote_).push_back(w);
    return Local::Skipped;
  }
  const TetId t = w.tet == kNoGid ? kNoTet : sub_.find_tet(w.tet, w.slot);
  if (w.tet != kNoGid && (t == kNoTet || sub_.deferred(t))) return Local::Gone;
  // Where the step's search starts: the tet itself, or for a step on ∂Ω a tet near its
  // element.
  const TetId from = w.a != kNoGid ? sub_.find_tet(w.near) : t;
  // No tet to start from here, or the search's own tet.
  if (from == kNoTet || locked_.contains(from)) {
    parked_.push_back(w);
    return Local::Done;
  }
  const bool tet_step = w.a == kNoGid && w.tet != kNoGid && rules_ != nullptr;
  const Point p = w.a != kNoGid ? w.p : rules_->point(sub_, t);
  const RootCavity& rc = search_.root_cavity(sub_, p, from, tet_step, reject(p, tet_step));
  if (rc.kind == RootCavity::Kind::Rejected) {
    defer_early(w, early_reason_);
    return Local::Done;
  }
  const auto locked = [&](TetId u) { return locked_.contains(u); };
  if (rc.kind != RootCavity::Kind::Complete ||
      std::any_of(rc.cavity.conflict.begin(), rc.cavity.conflict.end(), locked) ||
      std::any_of(rc.cavity.ring.begin(), rc.cavity.ring.end(), locked)) {
    if (rc.kind != RootCavity::Kind::Complete) {  // it needs other ranks
      room(remote_).push_back(w);
      remote_.back().parked = true;
    } else {  // a locked tet: tried again once the search ends
      parked_.push_back(w);
    }
    return Local::Done;
  }
  if (complete(rc.cavity, w)) ++stats_.local_while_waiting;
  return Local::Done;
}

bool InsertionActor::complete(const Cavity& c, const Waiting& w) {
  if (rules_ == nullptr) {
    sub_.insert(c, 0, 0);
    ++stats_.commits;
    return true;
  }
  const Verdict v = w.a != kNoGid ? rules_->accept_surface(sub_, c, w.a, w.b, w.c)
                                   : rules_->accept(sub_, c);
  if (v.kind == Verdict::Kind::Split || v.kind == Verdict::Kind::Facet) {
    Waiting first{v.p};
    first.a = v.a, first.b = v.b, first.c = v.c, first.near = v.near;
    first.origin = w.a == kNoGid ? w.tet : w.origin;
    first.setbacks = w.setbacks;
    if (active_)  // a local step while the search waits: it waits for the search's end
      parked_.push_back(first);
    else
      ready().push_front(first);
    return false;
  }
  if (v.kind == Verdict::Kind::Defer) {
    defer(w);
    return false;
  }
  if (w.a != kNoGid) ++(w.c == kNoGid ? stats_.splits : stats_.facet_points);
  rules_->commit(sub_, c);
  ++stats_.commits;
  committed_.push_back(c.point);
  made_.assign(sub_.created().begin(), sub_.created().end());
  for (const TetId t : made_) want(t);
  requeue_origin(w);
  return true;
}

void InsertionActor::defer(const Waiting& w) {
  if (w.a != kNoGid) {  // a step on ∂Ω: dropped
    requeue_origin(w);
    return;
  }
  ++stats_.deferred;
  if (const TetId t = sub_.find_tet(w.tet, w.slot); t != kNoTet) sub_.mark_deferred(t);
}

CavitySearch::Reject InsertionActor::reject(const Point& p, bool tet_step) {
  if (!tet_step || rules_ == nullptr || !rules_->defers_early()) return {};
  return [this, p](TetId u) { return (early_reason_ = rules_->defers_at(sub_, u, p)) != 0; };
}

void InsertionActor::defer_early(const Waiting& w, std::uint8_t reason) {
  ++stats_.deferred_early;
  rules_->count_early_deferral(reason);
  defer(w);
}

void InsertionActor::end_search_deferred(std::uint8_t reason) {
  const bool gone = sub_.find_tet(s_.w.tet) == kNoTet;
  finish();
  if (gone)
    ++stats_.gone;
  else
    defer_early(s_.w, reason);
}

void InsertionActor::requeue_origin(const Waiting& w) {
  if (w.a == kNoGid || w.origin == kNoGid) return;
  if (const TetId t = sub_.find_tet(w.origin); t != kNoTet) want(t);
}

void InsertionActor::charge_search(double seconds) {
  search_s_ += seconds;
  if (end_ == End::None) return;
  if (end_ == End::Commit)
    (search_distributed_ ? stats_.completed_distributed_s : stats_.completed_local_s) += search_s_;
  else if (end_ == End::Setback)
    stats_.setback_s += search_s_;
  else
    stats_.other_s += search_s_;
  search_s_ = 0;
  search_distributed_ = false;
  end_ = End::None;
}

bool InsertionActor::start(Waiting w) {
  if (w.a != kNoGid) {  // a step on ∂Ω: from a tet near its element, or any here
    TetId from = sub_.find_tet(w.near);
    if (from == kNoTet) from = any_real_tet();
    if (from == kNoTet) {
      requeue_origin(w);
      return false;
    }
    active_ = true;
    s_ = Search{next_search_++, w, sub_.tet_gid(from), 0, false, false};
    round();
    return true;
  }
  if (w.tet != kNoGid) {  // a tet's step: from the tet itself, while it is here
    const TetId t = sub_.find_tet(w.tet, w.slot);
    if (t == kNoTet || sub_.deferred(t)) return false;  // left, or deferred meanwhile
    w.p = rules_->point(sub_, t);
    active_ = true;
    s_ = Search{next_search_++, w, w.tet, 0, false, false};
    round();
    return true;
  }
  {
    const TetId start = any_real_tet();
    if (start == kNoTet) {  // nothing here to start from: the next rank takes the point
      WireWriter m;
      m.put(Type::Point).put(w.p).put(w.setbacks);
      send((sub_.id() + 1) % static_cast<ActorId>(t_.size()), m.take());
      ++stats_.points_passed;
    } else {
      active_ = true;
      s_ = Search{next_search_++, w, sub_.tet_gid(start), 0, false, false};
      round();
    }
  }
  return true;
}

TetId InsertionActor::any_real_tet() {
  const TetStore& st = sub_.store();
  if (sub_.real_tets() == 0) return kNoTet;
  for (std::size_t n = 0; n <= st.slots(); ++n) {
    if (cursor_ >= st.slots()) cursor_ = 0;
    const TetId t = cursor_++;
    if (st.is_alive(t) && !st.is_proxy(t)) return t;
  }
  return kNoTet;
}

void InsertionActor::round() {
  ++stats_.rounds;
  TetId hint = sub_.find_tet(s_.hint, s_.w.slot);
  if (hint == kNoTet) hint = any_real_tet();  // the hint was taken: start anywhere here
  if (hint == kNoTet) {                       // everything here was taken: start over
    setback();
    return;
  }
  // A tet's step: the cavity grows from the hint when it conflicts with p (the tet itself
  // while it is here), and the rules may defer the step at its first telling tet.
  const bool tet_step = s_.w.a == kNoGid && s_.w.tet != kNoGid && rules_ != nullptr;
  const RootCavity& rc =
      search_.root_cavity(sub_, s_.w.p, hint, tet_step, reject(s_.w.p, tet_step));
  if (rc.kind == RootCavity::Kind::Rejected) {
    // As a complete cavity's Defer, unless the tet has left (its holder steps it).
    end_search_deferred(early_reason_);
    return;
  }
  if (rc.kind == RootCavity::Kind::OnVertex) {
    ++stats_.duplicates;
    // A tet's step whose point is a vertex already (its rounded circumcenter): left to
    // the completion, marked like a deferred step, so that every bad tet left is marked.
    if (s_.w.tet != kNoGid)
      if (const TetId t = sub_.find_tet(s_.w.tet); t != kNoTet) sub_.mark_deferred(t);
    requeue_origin(s_.w);  // a step on ∂Ω: its point is there already
    finish();
    return;
  }
  if (rc.kind == RootCavity::Kind::Complete) {
    // A tet's step inserts its circumcenter only while the tet exists (here, in the
    // cavity): once another commit or a migration took it, p is no step of Fig. 2.
    const bool gone = s_.w.tet != kNoGid && sub_.find_tet(s_.w.tet, s_.w.slot) == kNoTet;
    finish();
    if (gone)
      ++stats_.gone;
    else if (complete(rc.cavity, s_.w))
      end_ = End::Commit;
    return;
  }
  if (rc.fetch.count(sub_.id()) != 0) {  // tets on their way here: look again later
    again_ = true;
    return;
  }
  locked_.clear();
  if (const TetId own = s_.w.tet == kNoGid ? kNoTet : sub_.find_tet(s_.w.tet, s_.w.slot); own != kNoTet)
    locked_.insert(own);  // the step's own tet: no local step or FETCH may take it
  if (rc.walk) {
    locked_.insert(hint);
  } else {
    locked_.insert(rc.cavity.conflict.begin(), rc.cavity.conflict.end());
    for (const TetId t : rc.cavity.ring)
      if (!sub_.store().is_proxy(t)) locked_.insert(t);
  }
  s_.walk = rc.walk;
  s_.refused = false;
  s_.rejected = 0;
  s_.outstanding = static_cast<int>(rc.fetch.size());
  search_distributed_ = search_distributed_ || !rc.fetch.empty();
  // The submeshes asked may defer the step at a tet of theirs, as root_cavity() here.
  const bool rejectable = tet_step && rules_->defers_early();
  for (const auto& [owner, sides] : rc.fetch) {
    WireWriter m;
    m.put(Type::Fetch).put(sub_.id()).put(s_.id).put(s_.w.p).put<std::uint8_t>(rc.walk);
    m.put<std::uint8_t>(rejectable);
    m.put_vector(sides);
    send(static_cast<int>(owner), m.take());
  }
}

void InsertionActor::finish() {
  end_ = End::Other;  // a commit or a setback says so after
  active_ = false;
  again_ = false;
  locked_.clear();
  ready(parked_.size());  // in their order, before the rest
  for (auto it = parked_.rbegin(); it != parked_.rend(); ++it) ready_.push_front(*it);
  parked_.clear();
}

void InsertionActor::setback() {
  ++stats_.setbacks;
  Waiting w = s_.w;
  ++w.setbacks;
  const std::uint64_t span = std::uint64_t{8} << std::min<std::uint32_t>(w.setbacks, 6);
  w.wake = tick_ + 1 + rng_() % span;
  delayed_.push_back(w);
  finish();
  end_ = End::Setback;
}

void InsertionActor::reply_in(bool refused, std::uint8_t rejected) {
  s_.refused = s_.refused || refused;
  if (s_.rejected == 0) s_.rejected = rejected;
  if (--s_.outstanding > 0) return;
  if (s_.rejected != 0)
    end_search_deferred(s_.rejected);  // a deferral is final: no retry would change it
  else if (s_.refused)
    setback();
  else
    round();
}

void InsertionActor::receive(int, std::span<const std::byte> bytes) {
  WireReader r(bytes);
  switch (r.get<Type>()) {
    case Type::Fetch: serve_fetch(r); break;
    case Type::Tets: take_tets(r); break;
    case Type::Refuse: reply_in(true); break;
    case Type::Reject: {
      r.get<std::uint64_t>();  // the search: always the active one
      reply_in(false, r.get<std::uint8_t>());
      break;
    }
    case Type::Relink: {
      std::vector<Relink> onward;  // notices to go on, as relink() readdressed them
      for (Relink n : r.get_vector<Relink>())
        if (!sub_.relink(n)) onward.push_back(n);
      send_relinks(onward);
      break;
    }
    case Type::Point: {
      const Point p = r.get<Point>();
      Waiting w{p};
      w.setbacks = r.get<std::uint32_t>();
      ready().push_back(w);
      break;
    }
  }
}

void InsertionActor::serve_fetch(WireReader& r) {
  const auto root = r.get<ActorId>();
  const auto search = r.get<std::uint64_t>();
  const auto p = r.get<Point>();
  const bool walk = r.get<std::uint8_t>() != 0;
  const bool rejectable = r.get<std::uint8_t>() != 0;
  const std::vector<Side> sides = r.get_vector<Side>();
  ++stats_.fetches_served;
  std::vector<Gid> wanted;
  bool refuse = false;
  for (const Side& x : sides) {
    refuse = refuse || sub_.find_tet(x.tet) == kNoTet;  // a stale claim
    wanted.push_back(x.tet);
  }
  std::vector<TetId> tets;
  if (!refuse) {
    CavitySearch::FetchSet f = search_.fetch_set(sub_, p, wanted, walk, reject(p, rejectable));
    if (f.rejected) {  // the step is deferred whatever else its cavity holds
      ++stats_.fetches_rejected;
      WireWriter m;
      m.put(Type::Reject).put(search).put(early_reason_);
      send(static_cast<int>(root), m.take());
      return;
    }
    tets = std::move(f.tets);
    refuse = std::any_of(tets.begin(), tets.end(), [&](TetId t) { return locked_.contains(t); });
  }
  if (refuse) {
    ++stats_.refused;
    WireWriter m;
    m.put(Type::Refuse).put(search);
    send(static_cast<int>(root), m.take());
    return;
  }
  std::vector<Relink> notes;
  const Migration mig = sub_.take(tets, root, notes);
  stats_.tets_sent += tets.size();
  send(static_cast<int>(root), migration_message(search, walk, mig));
  send_relinks(notes);
}

void InsertionActor::send_relinks(std::vector<Relink>& notes) {
  // One message per recipient, the notices in their order (a recipient applies them as
  // if they had come one by one: FIFO per pair keeps them after the tets sent before).
  std::stable_sort(notes.begin(), notes.end(),
                   [](const Relink& a, const Relink& b) { return a.recipient < b.recipient; });
  for (std::size_t i = 0; i < notes.size();) {
    std::size_t j = i;
    while (j < notes.size() && notes[j].recipient == notes[i].recipient) ++j;
    WireWriter m;
    m.put(Type::Relink).put_vector(std::vector<Relink>(notes.begin() + i, notes.begin() + j));
    send(static_cast<int>(notes[i].recipient), m.take());
    i = j;
  }
}

void InsertionActor::take_tets(WireReader& r) {
  r.get<std::uint64_t>();  // the search: always the active one (one search at a time)
  const bool walk = r.get<std::uint8_t>() != 0;
  Migration m;
  m.from = r.get<ActorId>();
  m.to = r.get<ActorId>();
  m.tets = r.get_vector<TetRecord>();
  m.vertices = r.get_vector<VertexRecord>();
  m.edge_labels = r.get_vector<EdgeLabel>();
  m.face_labels = r.get_vector<FaceLabel>();
  const std::vector<TetId> ids = sub_.give(m);
  if (walk && !ids.empty()) s_.hint = sub_.tet_gid(ids.front());
  for (const TetId t : ids) want(t);
  locked_.insert(ids.begin(), ids.end());  // the search's, until its next round
  reply_in(false);
}

}  // namespace pdr::par
