# Sourced by the build scripts: compile through ccache (which setup.sh installs), with paths taken
# relative to the checkout, so that a rebuild of the same sources in another clone on this machine
# (CI's, right after a session) reuses the objects instead of recompiling CGAL for half an hour.
compiler_cache=()
if command -v ccache >/dev/null; then
  compiler_cache=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=$PWD CCACHE_NOHASHDIR=1
fi
