// `pdr`: the command line. Parses the options once into each command's argument struct
// (docs/design.md §14), runs the command, and maps failures to exit codes (exit_codes.hpp):
// malformed input and bad usage exit 2 with "file:line: problem; what to do".
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <system_error>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "io/error.hpp"
#include "mesh/tet_store.hpp"

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
  cdel->add_option("--threads", del.threads, "Checker threads")->check(CLI::Range(1, 256));

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
  if (cdel->parsed()) return run_delaunay(del);
  if (cchk->parsed()) return run_check(chk);
  if (cmesh->parsed()) return run_mesh(mesh);
  return run_default(def);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return dispatch(argc, argv);
  } catch (const pdr::InputError& e) {
    std::cerr << "pdr: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::system_error& e) {
    std::cerr << "pdr: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const pdr::CapacityError& e) {
    // A resource limit like the vertex cap: exit 3 with the reason; nothing was written.
    std::cerr << "pdr: " << e.what() << "\n";
    return kExitNotGuaranteed;
  } catch (const std::bad_alloc&) {
    std::cerr << "pdr: out of memory\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "pdr: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}
