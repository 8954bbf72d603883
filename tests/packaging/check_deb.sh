#!/usr/bin/env bash
# Builds the .deb with CPack, unpacks it into a scratch root and checks its contents and metadata;
# then starts the unpacked app: it must still be running after a few seconds (it loaded its UI).
set -euo pipefail
build=$1
root=$2
cd "$build"
cpack -G DEB >/dev/null
deb=$(ls -t kontur_*_amd64.deb | head -n 1)
rm -rf "$root"
mkdir -p "$root"
dpkg-deb -x "$deb" "$root"
for f in usr/bin/kontur usr/bin/kontur-cli usr/share/applications/org.kontur.Kontur.desktop \
         usr/share/metainfo/org.kontur.Kontur.metainfo.xml usr/share/icons/hicolor/scalable/apps/org.kontur.Kontur.svg; do
  [ -e "$root/$f" ] || { echo "missing in $deb: $f"; exit 1; }
done
depends=$(dpkg-deb -f "$deb" Depends)
for dep in qml6-module-qtquick qml6-module-qtquick-controls libqt6quick6; do
  grep -q "$dep" <<<"$depends" || { echo "Depends lacks $dep: $depends"; exit 1; }
done
"$root/usr/bin/kontur" --version | grep -q "^kontur " || { echo "kontur --version failed"; exit 1; }
"$root/usr/bin/kontur-cli" --version | grep -q "^kontur-cli " || { echo "kontur-cli --version failed"; exit 1; }
status=0
timeout 4 "$root/usr/bin/kontur" --lang sk >"$root/run.log" 2>&1 || status=$?
if [ "$status" -ne 124 ]; then
  echo "the packaged kontur did not keep running (exit $status):"
  cat "$root/run.log"
  exit 1
fi
grep -E "qrc:|Error|error" "$root/run.log" && { echo "the packaged kontur printed errors"; exit 1; }
echo "package ok: $deb"
