#!/bin/sh
# Makes the README's pictures with `umbra render` (run from the repository
# root): sh docs/images/make.sh
# Set UMBRA to an umbra binary to skip the release build.
set -eu
if [ -z "${UMBRA:-}" ]; then
    cargo build --release -p umbra-cli
    UMBRA=target/release/umbra
fi
out=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The demo's process plant, seen from the front, right and above.
"$UMBRA" demo -o "$tmp/demo" --quiet > /dev/null
"$UMBRA" render "$tmp/demo/plant.obj" -o "$out/plant.png" --view iso --size 600x400

# A 2D Boolean: the union of the square with an octagonal hole and the star.
"$UMBRA" boolean union examples/a.wkt examples/b.wkt -o "$tmp/union.wkt" > /dev/null
"$UMBRA" render "$tmp/union.wkt" -o "$out/union.png" --size 600x400

# A figure eight in the dissertation's style: directed edges, vertices.
"$UMBRA" render examples/figure_eight.wkt -o "$out/figure_eight.png" --size 600x400 --style topology

# A slab pierced by a post, written as one mesh: `umbra check` finds the
# intersecting facet pairs, `--highlight` shows them.
cat > "$tmp/pierced.off" <<'END'
OFF
16 12 0
0 0 0
3 0 0
3 2 0
0 2 0
0 0 0.6
3 0 0.6
3 2 0.6
0 2 0.6
1.2 0.7 -0.8
1.8 0.7 -0.8
1.8 1.3 -0.8
1.2 1.3 -0.8
1.2 0.7 1.4
1.8 0.7 1.4
1.8 1.3 1.4
1.2 1.3 1.4
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
4 8 11 10 9
4 12 13 14 15
4 8 9 13 12
4 9 10 14 13
4 10 11 15 14
4 11 8 12 15
END
"$UMBRA" render "$tmp/pierced.off" -o "$out/pierced.png" --size 600x400 --style topology --highlight
