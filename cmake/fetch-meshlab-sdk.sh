#!/usr/bin/env bash
# Fetch the MeshLab plugin SDK (headers + vcglib) from Debian's own source package of the
# installed meshlab, with Debian's patches applied, into a cache folder. Nothing is committed:
# the build calls this when the cache is empty.
#
# usage: fetch-meshlab-sdk.sh CACHE_DIR
# prints the unpacked source tree's path on its last line.
set -euo pipefail

cache=${1:?usage: fetch-meshlab-sdk.sh CACHE_DIR}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)

version=$(dpkg-query -W -f='${Version}' meshlab 2>/dev/null || true)
if [ -z "$version" ]; then
  echo "fetch-meshlab-sdk: the meshlab package is not installed (apt-get install meshlab)" >&2
  exit 1
fi
upstream=${version%-*}          # 2020.09+dfsg1
upstream=${upstream#*:}
tree="$cache/meshlab-$upstream"
stamp="$tree/.voxelfair-sdk-$version"

if [ -f "$stamp" ]; then
  echo "$tree"
  exit 0
fi

command -v dpkg-source >/dev/null || { echo "fetch-meshlab-sdk: dpkg-dev is needed (apt-get install dpkg-dev)" >&2; exit 1; }

# A private apt configuration that adds the deb-src entry for the release the machine uses,
# so the machine's own sources list is left as it is.
apt_dir="$cache/apt"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/archives/partial"
codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
mirror=$(grep -rhoE 'https?://[^ ]*debian/?( |$)' /etc/apt/sources.list /etc/apt/sources.list.d/ 2>/dev/null \
         | grep -v security | head -n1 | tr -d ' ' || true)
mirror=${mirror:-http://deb.debian.org/debian}
echo "deb-src $mirror $codename main" > "$apt_dir/sources.list"
apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o "Dir::Etc::SourceParts=-"
          -o "Dir::State::Lists=$apt_dir/lists" -o "APT::Get::List-Cleanup=0")

echo "fetch-meshlab-sdk: downloading Debian's source of meshlab $version into $cache" >&2
apt-get "${apt_opts[@]}" update >&2
work=$(mktemp -d "$cache/download.XXXXXX")
( cd "$work" && apt-get "${apt_opts[@]}" source "meshlab=$version" >&2 )
rm -rf "$tree"
mv "$work/meshlab-$upstream" "$tree"
rm -rf "$work"

for needed in src/common/interfaces.h vcglib/vcg/complex/complex.h; do
  [ -f "$tree/$needed" ] || { echo "fetch-meshlab-sdk: $tree/$needed is missing after unpacking" >&2; exit 1; }
done
touch "$stamp"
echo "$tree"
