# Sourced by the scripts that configure a build tree (setup.sh, sanitize.sh, tsan.sh, fuzz.sh):
# the CMake generator they use. Ninja where it is installed (Debian's ninja-build; setup.sh
# installs it): it compiles a target's files while the libraries it links are still being built,
# where Make waits for each library, which on 2 cores takes a tenth to a third off a build
# (docs/testbed.md, "Build time"); Make otherwise.
if command -v ninja >/dev/null 2>&1; then
  dyop_generator=(-G Ninja)
  dyop_generator_name=Ninja
else
  dyop_generator=(-G "Unix Makefiles")
  dyop_generator_name="Unix Makefiles"
fi

# dyop_fresh_tree DIR: forgets DIR's configuration if another generator made it (CMake refuses to
# switch generators in place); what was built there is built again.
dyop_fresh_tree() {
  if [ -f "$1/CMakeCache.txt" ] &&
     ! grep -qx "CMAKE_GENERATOR:INTERNAL=$dyop_generator_name" "$1/CMakeCache.txt"; then
    rm -rf "$1/CMakeCache.txt" "$1/CMakeFiles"
  fi
}
