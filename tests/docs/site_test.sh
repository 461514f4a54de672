#!/usr/bin/env bash
# site_test.sh SOURCE_DIR SITE_DIR
# Builds the docs site (mkdocs.yml: docs/ with the README as its home page)
# with `mkdocs build --strict` into SITE_DIR, outside the source tree, and
# checks that every page of docs/ became a page of the site. Then holds strict
# mode to its word on a scratch copy of the docs: a broken link in a page, a
# broken link in the README, and a page left out of the nav each fail the
# build, naming the file. Skipped (77) where mkdocs is missing, unless
# CDVP_REQUIRE_MKDOCS is set (CI: scripts/setup.sh installs it).
set -euo pipefail
source_dir=$(realpath "$1")
site=$2
fail() { echo "docs site test: $*" >&2; exit 1; }

if ! command -v mkdocs > /dev/null; then
  [ -z "${CDVP_REQUIRE_MKDOCS:-}" ] || fail "mkdocs not found (scripts/setup.sh installs it)"
  echo "mkdocs not found: the docs site is not built"
  exit 77
fi
export PYTHONDONTWRITEBYTECODE=1  # the hooks module leaves no __pycache__ in the source tree
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# build ROOT SITE LOG: mkdocs build --strict of ROOT/mkdocs.yml into SITE.
build() { mkdocs build --strict --config-file "$1/mkdocs.yml" --site-dir "$2" > "$3" 2>&1; }

build "$source_dir" "$site" "$work/site.log" || { cat "$work/site.log"; fail "mkdocs build --strict failed"; }
grep -q 'A worked example' "$site/index.html" || fail "the site's home page is not the README"
for page in "$source_dir"/docs/*.md; do
  name=$(basename "$page" .md)
  [ -f "$site/$name.html" ] || fail "docs/$name.md has no page in the site"
done

# A scratch copy with three faults in one build: each must be named.
mkdir -p "$work/copy/scripts"
cp -r "$source_dir/docs" "$source_dir/README.md" "$source_dir/mkdocs.yml" "$work/copy/"
cp "$source_dir/scripts/mkdocs_hooks.py" "$work/copy/scripts/"
echo 'See [a page that is not there](no-such-page.md).' >> "$work/copy/docs/tutorial.md"
echo 'See [another page that is not there](docs/no-such-readme-link.md).' >> "$work/copy/README.md"
printf '# Orphan\n' > "$work/copy/docs/orphan.md"
if build "$work/copy" "$work/copy-site" "$work/copy.log"; then
  cat "$work/copy.log"
  fail "a site with broken links and a page missing from the nav was built without an error"
fi
for needle in "tutorial.md' contains a link to 'no-such-page.md'" "'no-such-readme-link.md'" "docs/orphan.md is not in the nav"; do
  grep -qF "$needle" "$work/copy.log" || { cat "$work/copy.log"; fail "the failed build does not say: $needle"; }
done
echo "docs site: $(ls "$site"/*.html | wc -l) pages in $site; strict mode refuses a broken link and a page left out of the nav"
