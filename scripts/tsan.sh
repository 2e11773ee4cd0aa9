#!/usr/bin/env bash
# Builds the threaded parts (particle placement with its look-ahead and field updates, the
# particle factory, synthesis) with ThreadSanitizer and runs their tests (CI runs this after
# scripts/sanitize.sh). Debian's libtbb is not instrumented, so the sanitizer cannot see the
# synchronisation between a task's spawn and its run and reports every parallel loop: TBB is
# built here from Debian's own source of the installed version, with -fsanitize=thread.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
source scripts/compilerCache.sh
# Built once per machine and version, outside the checkout, so that a clean clone on the same
# machine (CI's, after a session) reuses it; a lock keeps two runs from building it at once.
version=$(dpkg-query -W -f='${source:Version}' libtbb-dev)
tbb=${XDG_CACHE_HOME:-$HOME/.cache}/solidtex/tbb-tsan-${version//:/_}
mkdir -p "$(dirname "$tbb")"
exec 9>"$tbb.lock"
flock 9
if [ ! -e "$tbb/install/lib/libtbb.so.12" ]; then
  rm -rf "$tbb" && mkdir -p "$tbb/lists/partial" "$tbb/cache/archives/partial"
  # Debian's source archive through a private list, leaving the system's apt sources untouched.
  printf 'deb-src http://deb.debian.org/debian bookworm main\ndeb-src http://deb.debian.org/debian-security bookworm-security main\n' >"$tbb/sources.list"
  apt_src=(-qq -o Dir::Etc::SourceList="$tbb/sources.list" -o Dir::Etc::SourceParts=/dev/null
    -o Dir::State::Lists="$tbb/lists" -o Dir::Cache="$tbb/cache" -o APT::Sandbox::User=root)
  apt-get "${apt_src[@]}" update
  (cd "$tbb" && apt-get "${apt_src[@]}" source --download-only "onetbb=$version")
  tar -C "$tbb" -xf "$(ls "$tbb"/onetbb_*.orig.tar.* | grep -v '\.asc$' | head -1)"
  cmake -S "$(ls -d "$tbb"/oneTBB-*/)" -B "$tbb/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTBB_TEST=OFF \
    -DTBB_SANITIZE=thread -DTBBMALLOC_BUILD=OFF -DTBB_STRICT=OFF -DCMAKE_INSTALL_PREFIX="$tbb/install" >/dev/null
  cmake --build "$tbb/build" -j"$(nproc)"
  cmake --install "$tbb/build" >/dev/null
fi
exec 9>&-
cmake "${compiler_cache[@]}" -S . -B build-tsan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" \
  -DSOLIDTEX_TESTS=ON -DSOLIDTEX_STRICT=OFF -DSOLIDTEX_SANITIZE=thread
cmake --build build-tsan -j"$(nproc)" --target test_placement test_synthesis
# The instrumented TBB replaces Debian's (same version, same soname) for these runs only.
export LD_LIBRARY_PATH=$tbb/install/lib TSAN_OPTIONS="suppressions=$PWD/scripts/tsan.supp"
# Placement: every test but the accuracy checks the other builds run too (the exact spaciousness
# around a torus, and bricks' geometry beside their thread-count check), which took 117 of its 383
# seconds under the sanitizer.
placement_checks=*MatchesTheExactSpaciousnessAroundATorus*:PlaceInBricks.APeriodicVolume*
placement_checks+=:PlaceInBricks.BricksOfACountedBox*:PlaceInBricks.PlacesWholeSeparate*
build-tsan/tests/placement/test_placement --gtest_brief=1 --gtest_filter="-$placement_checks"
# Synthesis: its tests at small sizes (the thread-count checks of every method, with and without a
# frame field, among them); the quality checks at larger sizes take minutes each under the
# sanitizer and are left to the other builds.
slow=PeriodicAndSteered/RegionOfTheWholeVolume.*:*CircleField*:*LayersFollow*:*RepeatedTile*:*RealExemplar*
slow+=:*ProbingEveryCell*:*BedsLieAcrossZ*:*PeriodicVolumeHasNoSeam*:GrowSolid.IsTheSeedSolidGrown*
build-tsan/tests/synthesis/test_synthesis --gtest_brief=1 --gtest_filter="-$slow"
