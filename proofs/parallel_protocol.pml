/* parallel_protocol.pml: a Promela model of pdr's distributed cavity search (paper §4.1-4.3,
 * Fig. 7; docs/parallel.md "The protocol we are building"; src/par/insertion_actor.hpp),
 * checked with spin by tests/proofs/spin_protocol.sh.
 *
 * What is kept, as the code does it:
 *   - P ranks (2 or 3), one submesh each, single-threaded: every handler below is one atomic
 *     step of its rank, and a rank handles the messages that have arrived before it does
 *     anything of its own (InsertionActor::step polls first);
 *   - messages FETCH / TETS / REFUSE / RELINK (src/par/insertion_actor.cpp), FIFO per pair of
 *     ranks and unordered across pairs (par/transport.hpp): channel net[a*P+b] is what a sent
 *     to b and b has not seen yet; the network process moves it to b's inbox at any time;
 *   - a search at its root, in rounds: lock the closure tets held here, FETCH the others
 *     from the ranks the root's claims name, wait for every reply; all TETS: next round
 *     (the cavity may grow: the breadth-first search of §4.2); any REFUSE: a setback;
 *   - serving a FETCH: REFUSE when a requested tet is not here (a stale claim) or locked by
 *     this rank's own search, else migrate the tets to the root (TETS) and tell the third
 *     rank (RELINK: tets, new holder, epoch); a claim is replaced only by a newer epoch
 *     (Submesh, M3);
 *   - a setback unlocks everything; the tets that arrived stay at the root; the point
 *     waits a back-off of any length (the seeded random delay), then is queued again;
 *   - latency hiding: while its search waits, a rank commits cavities whose closure is all
 *     here and unlocked, or parks the point until the search ends;
 *   - termination detection exactly as par/termination.hpp: message counts and a dirty
 *     flag, two reduction rounds (reductions on their own channel: the globals red_*).
 *
 * What is abstracted:
 *   - the mesh is a ring of N = 6 or 8 tets (a tet's face neighbours are its two ring
 *     neighbours), partitioned into arcs; a tet set is a bit mask; a commit replaces the cavity's tets by new ones
 *     in the same place, so a node of the ring stands for "the tets at this place" and
 *     keeps its holder; the geometry is a nondeterministic choice: a search's cavity is any
 *     one or two adjacent tets containing a tet its root holds, and it may grow by one tet
 *     at a later round;
 *   - a rank knows a claim (holder, epoch) for every tet, where the code keeps claims on the
 *     proxies of its boundary only; one relink notice per migration goes to the third rank
 *     and is never forwarded; epochs come from one clock of migrations (below);
 *   - rank r has Wr insertions; the setbacks of a rank are bounded by MAXSB, after which
 *     the point is dropped (the code retries for ever with a doubling random back-off; spin
 *     has no probabilities, and an adversary that picks every back-off can make two ranks
 *     refuse each other for ever: the bound keeps the state space finite and the liveness
 *     property checkable; the random back-off is what makes the unbounded code end).
 *
 * Properties (assertions unless named):
 *   (1) Lemma 2: at a commit, the closure is held here and locked by this search, every
 *       closure tet was read by the search (acq), no other commit replaced a tet of it
 *       since it was read (hit: Fig. 3 overlapping or Fig. 4 neighbouring cavities), and
 *       no other commit's closure met it since (spoil): concurrently computed closures
 *       never overlap;
 *   (2) the process `ownership`: every tet is held by exactly one rank or is in exactly one
 *       TETS message (M1);
 *   (3) every message is expected where it arrives (a reply only to a waiting search),
 *       channels never overflow, and pan -q: no message is left at a valid end state, and
 *       no rank blocks before termination (invalid end states);
 *   (4) when a rank declares termination, no message is in flight or unread, no rank has
 *       a search, a queued or a delayed point, every insertion ended once (commit, drop),
 *       and every claim names the tet's holder (M3);
 *   liveness, `ltl terminates` (with -DLIVENESS; pan -a -f, weak fairness): every run
 *       ends with termination declared on every rank. The network process delivers any
 *       message it holds, so fairness makes every message arrive; a rank handles what has
 *       arrived before it starts a reduction round, as the code polls first.
 *
 * Mutation -DCAVITY_LOCKING_ONLY: the root fetches and locks only its cavity, reading the
 * ring from its proxies; spin must report violations of (1), of both kinds.
 *
 * Sizes (tests/proofs/spin_protocol.sh runs each exhaustively, 0.1 to 1.2 million states,
 * a few seconds each): safety on 2 ranks x 2 insertions with one retry; on 2 ranks on an
 * 8-tet ring split 5 + 3, where a rank commits locally while its search waits (on the
 * 6-tet ring no closure is ever free beside a waiting search); and on 3 ranks, two of them
 * searching, without retries (a setback drops the point: with retries 3 ranks exceed ten
 * million states). Liveness on 2 ranks x 1 insertion with two retries, and on the 8-tet
 * ring.
 */

#ifndef P
#define P 2
#endif
#ifndef W0  /* insertions per rank */
#define W0 1
#endif
#ifndef W1
#define W1 1
#endif
#ifndef W2
#define W2 1
#endif
#ifndef MAXSB
#define MAXSB 1
#endif

#ifndef N  /* tets in the ring: 6 or 8 */
#define N 6
#endif
#define ALL ((1 << N) - 1)
#define ROTL(c) ((((c) << 1) | ((c) >> (N - 1))) & ALL)
#define ROTR(c) ((((c) >> 1) | ((c) << (N - 1))) & ALL)
#define CLO(c) ((c) | ROTL(c) | ROTR(c))  /* closure: cavity and its face neighbours */
#ifdef CAVITY_LOCKING_ONLY
#define GATHER(c) (c)
#else
#define GATHER(c) CLO(c)  /* what the root fetches and locks */
#endif

/* The partition: arcs of the ring. */
#ifndef H0
#if P == 2
#define H0 (ALL >> (N / 2))
#define H1 (ALL & ~H0)
#else
#define H0 3
#define H1 12
#define H2 (ALL & ~15)
#endif
#endif

#define NQ 8  /* capacity of a channel: at most one FETCH, one reply and N relinks */
#define QUIET 0
#define COUNTING 1
#define CONFIRMING 2
#define DONE 3

mtype = { FETCH, TETS, REFUSE, RELINK };

chan net[P * P] = [NQ] of { mtype, byte, byte, byte };
chan inbox[P] = [2 * NQ] of { byte, mtype, byte, byte, byte };

/* Where tets are. */
byte held[P];          /* the rank's store */
byte transit;          /* tets in a TETS message */
byte cl[P * P];        /* cl[r*P+q]: the tets r believes q holds */
#if P == 3
/* Epochs order the claims a third rank hears of (with two ranks nobody else hears of a
 * move, so they are left out there: fewer states). The code counts each tet's moves; here
 * one clock counts all migrations, which orders the moves of each tet the same way. */
byte moves;            /* migrations so far */
byte cep[P * N];       /* the epoch of r's claim about each tet */
#define SET_CEP(t, e) cep[r * N + t] = e
#else
#define SET_CEP(t, e) skip
#endif

/* A rank's search and queue. */
bool act[P];           /* a search is active */
byte cav[P];           /* its cavity */
byte outst[P];         /* replies still to come */
bool refd[P];          /* a REFUSE came in this round */
bool park[P];          /* a local step needed other ranks: none until the search ends */
byte lkm[P];           /* tets locked by the rank's search */
byte work[P];          /* queued points */
byte dly[P];           /* points in back-off */
byte sb[P];            /* setbacks so far */

/* Ghost state for property (1): what the active search read, and what of it another
 * commit touched since. */
byte acq[P];
byte spoil[P];
byte hit[P];           /* ... and what of it another commit replaced (its cavity) */
byte ended;            /* insertions ended: committed or dropped */

/* Termination detection (par/termination.hpp) and the transport's counts. */
byte sent[P];
byte recv[P];
byte ts[P];
bool dirty[P];
bool bal[P];
byte snaps[P];
byte snapr[P];
byte rnd[P];           /* the round this rank started last, mod 4 */
byte red_rnd[2];       /* reduction slots by round parity: at most two rounds are open */
byte red_cnt[2];
byte red_s[2];
byte red_r[2];
byte red_d[2];

hidden byte t_, m_, q_, k_;

#if P == 2
#define OWNED_ONCE ((held[0] & held[1]) == 0 && (transit & (held[0] | held[1])) == 0 && \
                    (held[0] | held[1] | transit) == ALL)
#define ALL_DONE (ts[0] == DONE && ts[1] == DONE)
#else
#define OWNED_ONCE ((held[0] & held[1]) == 0 && (held[0] & held[2]) == 0 && \
                    (held[1] & held[2]) == 0 && \
                    (transit & (held[0] | held[1] | held[2])) == 0 && \
                    (held[0] | held[1] | held[2] | transit) == ALL)
#define ALL_DONE (ts[0] == DONE && ts[1] == DONE && ts[2] == DONE)
#endif

#if P == 2
#define WORK (W0 + W1)
#else
#define WORK (W0 + W1 + W2)
#endif
#define IDLE(r) (!act[r] && work[r] == 0 && dly[r] == 0)

/* The cavities: one tet, or two adjacent ones; OK(c) says which may be chosen. */
#define CAVITIES6(OK, v) \
  :: OK(1) -> v = 1   :: OK(2) -> v = 2   :: OK(4) -> v = 4 \
  :: OK(8) -> v = 8   :: OK(16) -> v = 16 :: OK(32) -> v = 32 \
  :: OK(3) -> v = 3   :: OK(6) -> v = 6   :: OK(12) -> v = 12 \
  :: OK(24) -> v = 24 :: OK(48) -> v = 48
#if N == 6
#define CAVITIES(OK, v) CAVITIES6(OK, v) :: OK(33) -> v = 33
#else
#define CAVITIES(OK, v) CAVITIES6(OK, v) \
  :: OK(64) -> v = 64 :: OK(128) -> v = 128 \
  :: OK(96) -> v = 96 :: OK(192) -> v = 192 :: OK(129) -> v = 129
#endif

inline send(to, mt, x, y, z) {
  assert(len(net[r * P + (to)]) < NQ);
  net[r * P + (to)]!mt, x, y, z;
  sent[r]++
}

/* r now believes the tets of m are at rank h, as of epoch e. */
inline claim(m, h, e) {
  for (q_ : 0 .. P - 1) { cl[r * P + q_] = cl[r * P + q_] & ~(m) };
  cl[r * P + (h)] = cl[r * P + (h)] | (m);
  for (q_ : 0 .. N - 1) {
    if
    :: ((m) & (1 << q_)) != 0 -> SET_CEP(q_, e)
    :: else -> skip
    fi
  };
  q_ = 0
}

/* Rank r's search ends (commit or setback): unlock, and the parked points may run again. */
inline finish() {
  act[r] = 0; cav[r] = 0; outst[r] = 0; refd[r] = 0; park[r] = 0;
  lkm[r] = 0; acq[r] = 0; spoil[r] = 0; hit[r] = 0
}

/* A commit of closure CLO(c) touches those tets: a search that read one of them is spoiled. */
inline touch(c, self) {
  for (q_ : 0 .. P - 1) {
    if
    :: q_ != r || !self ->
       spoil[q_] = spoil[q_] | (CLO(c) & acq[q_]); hit[q_] = hit[q_] | ((c) & acq[q_])
    :: else -> skip
    fi
  };
  ended++
}

inline setback() {
  printf("rank %d: setback\n", r);
  finish();
  if
  :: sb[r] < MAXSB -> sb[r]++; dly[r]++
  :: else -> ended++  /* the model's bound: the point is dropped */
  fi
}

/* One round of r's search (InsertionActor::round); `later`: not the first, so the tets that
 * came may show the cavity to be larger (one tet grows to two). */
inline round(later) {
  if
  :: later && (cav[r] & (cav[r] - 1)) == 0 ->
     if
     :: cav[r] = cav[r] | ROTL(cav[r])
     :: cav[r] = cav[r] | ROTR(cav[r])
     :: skip
     fi
  :: else -> skip
  fi;
  lkm[r] = lkm[r] | (GATHER(cav[r]) & held[r]);
  acq[r] = acq[r] | (CLO(cav[r]) & held[r]) | (CLO(cav[r]) & ~GATHER(cav[r]));
  m_ = GATHER(cav[r]) & ~held[r];
  if
  :: m_ == 0 ->  /* complete: commit (Lemma 2's condition, property (1)) */
     assert((GATHER(cav[r]) & ~held[r]) == 0 && (GATHER(cav[r]) & ~lkm[r]) == 0);
     assert((CLO(cav[r]) & ~acq[r]) == 0);
     printf("rank %d commits cavity %d, closure %d\n", r, cav[r], CLO(cav[r]));
     assert(hit[r] == 0);    /* Fig. 3, 4: no cavity met since overlaps or neighbours this one */
     assert(spoil[r] == 0);  /* Lemma 2: no closure met since overlaps this one */
     touch(cav[r], 1);
     finish()
  :: else ->
     refd[r] = 0;
     for (k_ : 0 .. P - 1) {
       if
       :: k_ != r && (m_ & cl[r * P + k_]) != 0 ->
          printf("rank %d fetches %d from rank %d\n", r, m_ & cl[r * P + k_], k_);
          send(k_, FETCH, m_ & cl[r * P + k_], 0, 0); outst[r]++;
          m_ = m_ & ~cl[r * P + k_]
       :: else -> skip
       fi
     };
     assert(m_ == 0)  /* every tet needed is claimed by another rank */
  fi;
  m_ = 0; k_ = 0
}

inline serve_fetch(root, m) {
  if
  :: (m & ~held[r]) != 0 || (m & lkm[r]) != 0 ->
     printf("rank %d refuses %d to rank %d\n", r, m, root);
     send(root, REFUSE, 0, 0, 0)
  :: else ->
     printf("rank %d migrates %d to rank %d\n", r, m, root);
     held[r] = held[r] & ~m;
     assert((transit & m) == 0);
     transit = transit | m;
#if P == 3
     moves++;
     claim(m, root, moves);
     send(3 - r - root, RELINK, m, root, moves);
     send(root, TETS, m, moves, 0)
#else
     claim(m, root, 0);
     send(root, TETS, m, 0, 0)
#endif
  fi
}

inline reply_in() {
  outst[r]--;
  if
  :: outst[r] > 0 -> skip
  :: outst[r] == 0 && refd[r] -> setback()
  :: else -> round(1)
  fi
}

inline take_tets(m, e) {
  assert(act[r] && outst[r] > 0);  /* a reply only to the waiting search */
  assert((transit & m) == m);
  transit = transit & ~m;
  held[r] = held[r] | m;
  lkm[r] = lkm[r] | m;  /* the search's, until it ends */
  acq[r] = acq[r] | m;
  claim(m, r, e);
  reply_in()
}

#if P == 3
inline relink(m, h, e) {
  assert(h != r);
  for (t_ : 0 .. N - 1) {
    if
    :: (m & (1 << t_)) != 0 && e > cep[r * N + t_] -> claim(1 << t_, h, e)
    :: else -> skip  /* not in m, or an older claim than the one r has */
    fi
  };
  t_ = 0
}
#endif

/* Every rank's part of the reduction round it starts now. */
inline contribute(s, rv, d) {
  rnd[r] = (rnd[r] + 1) % 4;
  q_ = rnd[r] % 2;
  if
  :: red_rnd[q_] != rnd[r] ->
     red_rnd[q_] = rnd[r]; red_cnt[q_] = 0; red_s[q_] = 0; red_r[q_] = 0; red_d[q_] = 0
  :: else -> skip
  fi;
  red_cnt[q_]++; red_s[q_] = red_s[q_] + s; red_r[q_] = red_r[q_] + rv; red_d[q_] = red_d[q_] + d;
  q_ = 0
}
#define RESULT(r) (red_rnd[rnd[r] % 2] == rnd[r] && red_cnt[rnd[r] % 2] == P)

/* Property (4): the run is over when a rank says so. */
inline over() {
  for (k_ : 0 .. P * P - 1) { assert(len(net[k_]) == 0) };
  for (k_ : 0 .. P - 1) {
    assert(len(inbox[k_]) == 0);
    assert(!act[k_] && work[k_] == 0 && dly[k_] == 0);
    for (q_ : 0 .. P - 1) { assert(cl[k_ * P + q_] == held[q_]) }
  };
  assert(transit == 0 && ended == WORK);
  k_ = 0; q_ = 0
}

#define START_OK(c) (((c) & held[r]) != 0)
#define LOCAL_OK(c) ((GATHER(c) & ~(held[r] & ~lkm[r])) == 0)

proctype rank(byte r) {
  byte f, a, b, c;
  mtype mt;
  do
  :: atomic { nempty(inbox[r]) ->
       inbox[r]?f, mt, a, b, c;
       recv[r]++; dirty[r] = 1;
       if
       :: mt == FETCH -> serve_fetch(f, a)
       :: mt == TETS -> take_tets(a, b)
       :: mt == REFUSE -> assert(act[r] && outst[r] > 0); refd[r] = 1; reply_in()
#if P == 3
       :: mt == RELINK -> relink(a, b, c)
#endif
       :: else -> assert(false)
       fi;
       f = 0; mt = 0; a = 0; b = 0; c = 0 }
  :: atomic { empty(inbox[r]) && !act[r] && work[r] > 0 ->  /* start a search */
       work[r]--; dirty[r] = 1;
       if
       :: held[r] == 0 -> ended++  /* nothing here to start from: the step's tet has gone */
       CAVITIES(START_OK, cav[r])
       fi;
       if
       :: cav[r] != 0 ->
          printf("rank %d searches cavity %d, closure %d\n", r, cav[r], CLO(cav[r]));
          act[r] = 1; round(0)
       :: else -> skip
       fi }
  :: atomic { empty(inbox[r]) && act[r] && outst[r] > 0 && work[r] > 0 && !park[r] ->
       dirty[r] = 1;  /* a local step while the search waits */
       if
       CAVITIES(LOCAL_OK, c)
       :: else -> park[r] = 1
       fi;
       if
       :: c != 0 ->
          assert((GATHER(c) & ~held[r]) == 0 && (GATHER(c) & lkm[r]) == 0);
          printf("rank %d commits cavity %d locally, closure %d\n", r, c, CLO(c));
          work[r]--; touch(c, 0); c = 0
       :: else -> skip
       fi }
  :: atomic { empty(inbox[r]) && dly[r] > 0 ->  /* a back-off ends */
       dly[r]--; work[r]++; dirty[r] = 1 }
  :: atomic { empty(inbox[r]) && ts[r] == QUIET && IDLE(r) ->
       dirty[r] = 0; snaps[r] = sent[r]; snapr[r] = recv[r];
       contribute(sent[r], recv[r], 0);
       ts[r] = COUNTING }
  :: atomic { empty(inbox[r]) && ts[r] == COUNTING && RESULT(r) ->
       k_ = rnd[r] % 2;
       bal[r] = red_s[k_] == red_r[k_];
       a = dirty[r] || !IDLE(r) || sent[r] != snaps[r] || recv[r] != snapr[r];
       contribute(0, 0, a);
       a = 0; k_ = 0; ts[r] = CONFIRMING }
  :: atomic { empty(inbox[r]) && ts[r] == CONFIRMING && RESULT(r) ->
       if
       :: bal[r] && red_d[rnd[r] % 2] == 0 -> over(); ts[r] = DONE
       :: else -> ts[r] = QUIET
       fi;
       bal[r] = 0; snaps[r] = 0; snapr[r] = 0 }
  :: ts[r] == DONE -> break
  od
}

active proctype network() {
  byte a, b, c;
  mtype mt;
end:
  do
#define MOVE(i, j) \
  :: atomic { nempty(net[i * P + j]) -> net[i * P + j]?mt, a, b, c; \
              inbox[j]!i, mt, a, b, c; mt = 0; a = 0; b = 0; c = 0 }
  MOVE(0, 1)
  MOVE(1, 0)
#if P == 3
  MOVE(0, 2)
  MOVE(2, 0)
  MOVE(1, 2)
  MOVE(2, 1)
#endif
  od
}

/* Property (2), in every state from the partition on. */
proctype ownership() {
end:
  atomic { !OWNED_ONCE -> assert(false) }
}

init {
  atomic {
    held[0] = H0; held[1] = H1;
#if P == 3
    held[2] = H2;
#endif
    work[0] = W0; work[1] = W1;
#if P == 3
    work[2] = W2;
#endif
    for (k_ : 0 .. P - 1) {
      for (q_ : 0 .. P - 1) { cl[k_ * P + q_] = held[q_] }
    };
    k_ = 0; q_ = 0;
    run ownership();
    for (k_ : 0 .. P - 1) { run rank(k_) };
    k_ = 0
  }
}

#ifdef LIVENESS
ltl terminates { <> ALL_DONE }
#endif
