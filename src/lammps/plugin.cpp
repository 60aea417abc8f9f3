// Plugin entry point: registers fix style "hardcontact".
//
// Used two ways with the same code:
//  - `plugin load hardcontactplugin.so` in a LAMMPS with the PLUGIN package: LAMMPS calls
//    lammpsplugin_init(lmp, dlopen handle, its plugin registration function);
//  - build/lmp_hardcontact (main.cpp) calls it right after creating the LAMMPS instance, with
//    a registration function that inserts the creator into lmp->modify->fix_map.

// the prototype in lammpsplugin.h must be exported although this library is built with
// -fvisibility=hidden
#pragma GCC visibility push(default)
#include "lammpsplugin.h"
#pragma GCC visibility pop

#include "fix_hardcontact.h"
#include "version.h"

using namespace LAMMPS_NS;

namespace {

Fix *hardcontact_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixHardContact(lmp, narg, arg);
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto register_plugin = reinterpret_cast<lammpsplugin_regfunc>(regfunc);

  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "fix";
  plugin.name = "hardcontact";
  plugin.info = "fix hardcontact: non-smooth inelastic contact of spheres (B. Maury, Numer. Math. "
                "2006), integrator replacing pair gran/* + fix nve/sphere";
  plugin.author = "hardcontact developers";
  // same cast as LAMMPS's own plugins: a Fix * is returned where a void * is declared
  plugin.creator.v2 = reinterpret_cast<lammpsplugin_factory2 *>(&hardcontact_creator);
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);
}
