// `pdr`: the command line. Parses the options once into each command's argument struct
// (docs/design.md §14), runs the command, and maps failures to exit codes (exit_codes.hpp):
// malformed input and bad usage exit 2 with "file:line: problem; what to do".
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <sstream>
#include <streambuf>
#include <string>
#include <utility>
#include <system_error>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/parallel.hpp"
#include "io/error.hpp"
#include "mesh/tet_store.hpp"
#include "par/affinity.hpp"
#include "par/mpi_transport.hpp"
#include "par/rank_files.hpp"

namespace {

using namespace pdr::app;

void add_formats(CLI::App* cmd, std::vector<std::string>& formats) {
  cmd->add_option("--formats", formats, "Output formats, comma separated: node,vtu,msh,mesh")
      ->delimiter(',')
      ->capture_default_str();
}

int dispatch(int argc, char** argv) {
  CLI::App app{
      "pdr: guaranteed-quality Delaunay refinement for polyhedral domains.\n"
      "Without a command: the default job (see README.md, Quick start)."};
  app.set_version_flag("--version", "pdr 0.1.0");
  app.require_subcommand(0, 1);

  DefaultArgs def;
  app.add_option("-o,--output", def.prefix, "Output prefix of the default job")
      ->capture_default_str();
  app.add_flag("--json", def.json, "Print the summary as one JSON object");

  DelaunayArgs del;
  auto* cdel = app.add_subcommand("delaunay", "Delaunay tetrahedralization of a point set");
  cdel->add_option("points", del.points, "TetGen .node file")->required()->check(
      CLI::ExistingFile);
  cdel->add_option("-o,--output", del.prefix, "Output prefix")->required();
  add_formats(cdel, del.formats);
  cdel->add_flag("!--no-check", del.check, "Skip the exact check of the result");
  cdel->add_flag("--json", del.json, "Print the summary as one JSON object");
  cdel->add_option("--threads", del.threads, "Checker threads (default: every CPU it may use)")
      ->check(CLI::Range(1, 256));

  MeshArgs mesh;
  CLI::App* cmesh = add_mesh_command(app, mesh);

  CheckArgs chk;
  CLI::App* cchk = add_check_command(app, chk);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  // Under mpirun only `pdr mesh` (and the default job) is parallel; the other commands
  // run on rank 0 alone (the others would write the same files at once).
  if ((cdel->parsed() || cchk->parsed()) && world().rank != 0) return kExitOk;
  if (cdel->parsed()) return run_delaunay(del);
  if (cchk->parsed()) return run_check(chk);
  if (cmesh->parsed()) return run_mesh(mesh);
  return run_default(def);
}

// The exit code of the exception that ended a command, and what to say about it.
std::pair<int, std::string> exit_code_of(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const pdr::InputError& e) {
    return {kExitBadInput, e.what()};
  } catch (const std::system_error& e) {
    return {kExitBadInput, e.what()};
  } catch (const pdr::CapacityError& e) {
    // A resource limit like the vertex cap: exit 3 with the reason; nothing was written.
    return {kExitNotGuaranteed, e.what()};
  } catch (const std::bad_alloc&) {
    return {kExitInternal, "out of memory"};
  } catch (const std::exception& e) {
    return {kExitInternal, std::string("internal error: ") + e.what()};
  }
}

// The command's exit code (one process, no mpirun).
int run(int argc, char** argv) {
  try {
    return dispatch(argc, argv);
  } catch (...) {
    const auto [code, what] = exit_code_of(std::current_exception());
    std::cerr << "pdr: " << what << "\n";
    return code;
  }
}

// A stream buffer that drops everything: the standard streams of ranks other than 0.
class NullBuffer final : public std::streambuf {
 protected:
  int_type overflow(int_type c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// Under mpirun (app/parallel.hpp): every rank runs the command; only rank 0 prints (the
// others' standard streams are muted, so a bad input is reported once; a rank that fails
// where rank 0 did not says so at the end); every rank ends
// with rank 0's exit code. A rank whose run ends in an exception other than bad input
// (which every rank meets alike, before any exchange) ends the whole run at once, with
// MPI_Abort and its exit code: the other ranks may be waiting for it.
int run_ranks(int argc, char** argv) {
  pdr::par::MpiSession session(&argc, &argv);
  world().rank = session.rank();
  world().size = session.size();
  NullBuffer muted;
  std::ostringstream held;  // this rank's error messages, said only if rank 0 did not fail
  std::streambuf* const out = std::cout.rdbuf();
  std::streambuf* const err = std::cerr.rdbuf();
  if (session.rank() != 0) {
    std::cout.rdbuf(&muted);
    std::cerr.rdbuf(held.rdbuf());
  }
  int code = kExitOk;
  bool abandoned = false;
  try {
    code = dispatch(argc, argv);
  } catch (const pdr::InputError& e) {
    std::cerr << "pdr: " << e.what() << "\n";
    code = kExitBadInput;
  } catch (const pdr::par::RankFilesError& e) {
    // Rank 0 alone, with every rank past the write (par/rank_files.hpp): said once, and
    // every rank ends with its exit 2 below.
    std::cerr << "pdr: " << e.what() << "\n";
    code = kExitBadInput;
  } catch (const RunAbandoned&) {
    abandoned = true;  // another rank failed, and says why
    code = *world().decided;
  } catch (...) {
    const auto [failed, what] = exit_code_of(std::current_exception());
    std::fprintf(stderr, "pdr: rank %d: %s\n", session.rank(), what.c_str());
    if (session.size() > 1) pdr::par::MpiSession::abort(failed);
    code = failed;
  }
  const int mine = code;
  code = agree_exit_code(code);
  // A failure that rank 0 did not meet (a file missing on one host): said by this rank.
  if (mine != kExitOk && !abandoned && session.rank() != 0 && !world().root_failed)
    std::fprintf(stderr, "pdr: rank %d failed:\n%s", session.rank(), held.str().c_str());
  std::cout.flush();
  std::cout.rdbuf(out);
  std::cerr.rdbuf(err);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  // One rank is the sequential command: MPI is not even initialised (its memory hooks and
  // start-up would cost the sequential kernel about 10%).
  if (pdr::par::launched_by_mpi() && pdr::par::launcher_world_size() != 1)
    return run_ranks(argc, argv);
  // A single rank under mpirun is bound to one core, which its threads would share.
  if (pdr::par::launched_by_mpi()) pdr::par::use_every_cpu();
  return run(argc, argv);
}
