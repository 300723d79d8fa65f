#!/usr/bin/env bash
# The project as a user installs it (cmake --install, and the Debian package
# CPack builds), checked from outside the build tree:
#   1. installed programs report the version;
#   2. a program of another project builds against the installed tree with
#      find_package(dem) and reproduces the installed dem_run bit for bit;
#   3. the installed Python package imports with its extension from the
#      installed tree, reports the version and finds the installed programs;
#   4. cpack makes dem_<version>_amd64.deb with the programs, the Python
#      package, the data and the shared-library dependencies, and
#      dem-dev_<version>_amd64.deb with the libraries, headers and CMake
#      configuration and the -dev packages that configuration needs; each
#      with Debian's copyright file.
#   install_test.sh SOURCE_DIR BUILD_DIR WORK_DIR VERSION
set -euo pipefail
source_dir="$1" build="$2" work="$3" version="$4"
rm -rf "$work" && mkdir -p "$work"
prefix="$work/prefix"
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for program in dem_run dem_validate dem_vtk dem_server demctl; do
  out="$("$prefix/bin/$program" --version)" || fail "$program --version exited $?"
  [ "$out" = "$program $version" ] || fail "$program --version said \"$out\", expected \"$program $version\""
  echo "ok: $out"
done

# A case run by the installed dem_run, from the installed cases.
case_file="$prefix/share/dem/cases/ball/nine_disc_damped.case.txtpb"
"$prefix/bin/dem_run" "$case_file" --out "$work/run" --quiet --threads 1
cmake -S "$source_dir/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >"$work/consumer.log" 2>&1 || { cat "$work/consumer.log" >&2; fail "find_package(dem)"; }
cmake --build "$work/consumer" -j2 >>"$work/consumer.log" 2>&1 || { cat "$work/consumer.log" >&2; fail "building against the installed tree"; }
"$work/consumer/dem_consumer" "$case_file" "$work/run/final.snapshot" || fail "the consumer's run differs from dem_run's"
echo "ok: find_package(dem) consumer"

# The Python package from the installed tree only (not the build's).
python_dir="$prefix/lib/python3/dist-packages"
env -u PYTHONPATH PYTHONPATH="$python_dir" /usr/bin/python3 - "$prefix" "$version" <<'PY' || fail "the installed Python package"
import pathlib, sys
import dem, dem._client
prefix, version = pathlib.Path(sys.argv[1]), sys.argv[2]
assert dem.__version__ == version, dem.__version__
assert pathlib.Path(dem._client.__file__).is_relative_to(prefix), dem._client.__file__
assert dem.paths.server_program() == prefix / "bin" / "dem_server", dem.paths.server_program()
assert (dem.paths.cases_dir() / "ball" / "nine_disc_damped.case.txtpb").is_file(), dem.paths.cases_dir()
assert dem.paths.sweep_task_script().is_file(), dem.paths.sweep_task_script()
import dem.sweep
print(f"ok: import dem {dem.__version__} from {pathlib.Path(dem.__file__).parent}")
PY

# The Debian package.
(cd "$work" && cpack --config "$build/CPackConfig.cmake" -B "$work/deb" >"$work/cpack.log" 2>&1) ||
  { tail -30 "$work/cpack.log" >&2; fail "cpack"; }
deb="$work/deb/dem_${version}_amd64.deb"
[ -f "$deb" ] || fail "no $deb"
dpkg-deb --info "$deb" >"$work/deb_info.txt"
dpkg-deb --contents "$deb" >"$work/deb_contents.txt"
for dependency in libddsc0debian libprotobuf libssl3 python3-numpy python3-protobuf; do
  grep -q "Depends:.*$dependency" "$work/deb_info.txt" || fail "the package does not depend on $dependency"
done
for file in ./usr/bin/dem_server ./usr/bin/demctl ./usr/bin/dem_run ./usr/share/dem/cases/miyata/cs.case.txtpb \
    ./usr/lib/python3/dist-packages/dem/__init__.py ./usr/share/doc/dem/LICENSE ./usr/share/dem/ros2/dem_interfaces/package.xml; do
  grep -q " $file\$" "$work/deb_contents.txt" || fail "the package lacks $file"
done
grep -q "./usr/lib/python3/dist-packages/dem/_client.cpython-.*\.so" "$work/deb_contents.txt" || fail "the package lacks dem._client"
if grep -q "/usr/include/\|/cmake/dem/" "$work/deb_contents.txt"; then fail "dem holds dem-dev's files"; fi
echo "ok: $(basename "$deb") ($(du -k "$deb" | cut -f1) kB)"
dev="$work/deb/dem-dev_${version}_amd64.deb"
[ -f "$dev" ] || fail "no $dev"
dpkg-deb --info "$dev" >"$work/dev_info.txt"
dpkg-deb --contents "$dev" >"$work/dev_contents.txt"
# demConfig.cmake's find_dependency calls, and the runtime package of the same version.
for dependency in "dem (= $version)" libeigen3-dev libprotobuf-dev libssl-dev cyclonedds-dev; do
  grep -qF "$dependency" <(grep "Depends:" "$work/dev_info.txt") || fail "dem-dev does not depend on $dependency"
done
for file in ./usr/lib/cmake/dem/demConfig.cmake ./usr/include/dem/world.h ./usr/include/dem/client/client.h \
    ./usr/lib/libdem_engine.a; do
  grep -q " $file\$" "$work/dev_contents.txt" || fail "dem-dev lacks $file"
done
echo "ok: $(basename "$dev") ($(du -k "$dev" | cut -f1) kB): $(sed -n 's/^ Depends: //p' "$work/dev_info.txt")"
# Debian's copyright file, machine-readable, in each package.
for package in dem dem-dev; do
  contents="$work/deb_contents.txt"
  [ $package = dem ] || contents="$work/dev_contents.txt"
  grep -q " ./usr/share/doc/$package/copyright\$" "$contents" || fail "$package has no /usr/share/doc/$package/copyright"
done
dpkg-deb --fsys-tarfile "$deb" | tar -xO ./usr/share/doc/dem/copyright >"$work/copyright"
head -1 "$work/copyright" | grep -q "^Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/" ||
  fail "the copyright file is not in Debian's format"
grep -q "^License: Expat" "$work/copyright" && grep -q "^Copyright: .*the dem contributors" "$work/copyright" ||
  fail "the copyright file names no licence or holder"
echo "ok: /usr/share/doc/dem/copyright and /usr/share/doc/dem-dev/copyright (Expat)"
