#!/usr/bin/env bash
# Rebuild three.min.js: the classes of three.js listed in three-entry.js, bundled into one
# minified script that defines the global THREE (inlined by `routh animate` in its page).
# Needs node and npm; three and esbuild come from the npm registry at the versions below.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$here/three-entry.js" "$work/"
cd "$work"
npm init -y >/dev/null
npm install --no-audit --no-fund --silent three@0.187.0 esbuild@0.28.2
./node_modules/.bin/esbuild three-entry.js --bundle --format=iife --global-name=THREE \
  --minify --legal-comments=inline --target=es2020 --log-level=warning --outfile=three.min.js
cp node_modules/three/LICENSE "$here/three-LICENSE.txt"
if grep -qi '</script' three.min.js; then
  echo "three.min.js contains </script: it cannot be inlined" >&2
  exit 1
fi
cp three.min.js "$here/three.min.js"
echo "wrote $here/three.min.js ($(wc -c <"$here/three.min.js") bytes)"
