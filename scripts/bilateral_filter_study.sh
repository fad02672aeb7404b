#!/usr/bin/env bash
# The image-subsampling study of doc/sampling.md (dissertation Sec. 2.2.3): `featurerecon bilateral-filter`
# over budgets of 0.1 to 2 taps per kernel pixel, uniform and bilateral taps (with and without density
# compensation), local and global patterns, on the shared images. Writes doc/data/bilateral_filter_study.csv,
# one SVG plot of PSNR against taps per image and mode (doc/images/bilateral_filter_<image>.svg), and the
# sample ratio bilateral/uniform at equal PSNR per image and mode (doc/data/bilateral_filter_ratios.csv).
# FEATURERECON=path/to/featurerecon (default build/src/featurerecon), IMAGES=folder (default
# ../shared/data/images), SEED=N (default 0).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${FEATURERECON:-build/src/featurerecon}
images=${IMAGES:-../shared/data/images}
seed=${SEED:-0}
budgets="0.1 0.15 0.2 0.3 0.4 0.5 0.7 1 1.4 2"
mkdir -p doc/data doc/images
csv=doc/data/bilateral_filter_study.csv
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "image,mode,sampling,budget,taps_per_kernel_pixel,psnr_db,ssim,seconds,exact_seconds" > "$csv"
for image in notes.png baboon.jpg fruits.jpg; do
  name=${image%.*}
  for mode in global local; do
    for variant in uniform bilateral bilateral-uncompensated; do
      sampling=${variant%-uncompensated}
      extra=""
      [ "$variant" = bilateral-uncompensated ] && extra="--no-compensation"
      for budget in $budgets; do
        json=$("$bin" bilateral-filter "$images/$image" --sampling "$sampling" --mode "$mode" --budget "$budget" \
               --seed "$seed" $extra --out "$tmp/out.png" --quiet)
        field() { echo "$json" | sed -E "s/.*\"$1\": ([^,}]*).*/\1/"; }
        echo "$name,$mode,$variant,$budget,$(field taps_per_kernel_pixel),$(field psnr_db),$(field ssim),$(field seconds),$(field exact_seconds)" | tee -a "$csv"
      done
    done
  done
done

# Sample ratio at equal quality: for every bilateral point, the uniform budget reaching the same PSNR
# (linear in PSNR against log taps between the neighbouring uniform points), and taps_bilateral / taps_uniform.
{ echo "image,mode,sampling,taps,psnr_db,uniform_taps_at_same_psnr,ratio"
awk -F, 'NR > 1 { key = $1 "," $2; n[key "," $3]++; t[key "," $3 "," n[key "," $3]] = $5; p[key "," $3 "," n[key "," $3]] = $6; keys[key] = 1 }
END {
  for (key in keys) for (v = 1; v <= 2; ++v) {
    s = v == 1 ? "bilateral" : "bilateral-uncompensated"; u = key ",uniform"
    for (i = 1; i <= n[key "," s]; ++i) {
      q = p[key "," s "," i]; match_t = ""
      for (j = 1; j < n[u]; ++j) {
        a = p[u "," j]; b = p[u "," j + 1]
        if ((a <= q && q <= b) || (b <= q && q <= a)) {
          f = b == a ? 0 : (q - a) / (b - a)
          match_t = exp(log(t[u "," j]) + f * (log(t[u "," j + 1]) - log(t[u "," j]))); break
        }
      }
      if (match_t != "") printf "%s,%s,%.4f,%.3f,%.4f,%.3f\n", key, s, t[key "," s "," i], q, match_t, t[key "," s "," i] / match_t
      else printf "%s,%s,%.4f,%.3f,,\n", key, s, t[key "," s "," i], q
    }
  }
}' "$csv" | sort; } > doc/data/bilateral_filter_ratios.csv

# One plot per image: PSNR (dB) against taps per kernel pixel (log scale), global and local side by side.
for name in notes baboon fruits; do
  awk -F, -v name="$name" 'BEGIN {
    W = 360; H = 260; L = 50; B = 40; T = 30; xmin = log(0.08); xmax = log(2.5)
    colour["uniform"] = "#1f77b4"; colour["bilateral"] = "#d62728"; colour["bilateral-uncompensated"] = "#ff9896"
  }
  NR > 1 && $1 == name { k = $2 "," $3; pts[k] = pts[k] " " $5 ":" $6; if ($6 != "null") { if (lo == "" || $6 < lo) lo = $6; if (hi == "" || $6 > hi) hi = $6 } }
  END {
    lo = int(lo / 5) * 5; hi = int(hi / 5 + 1) * 5
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"11\">\n", 2 * W + 20, H + 40
    printf "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n"
    split("global local", modes, " ")
    for (m = 1; m <= 2; ++m) {
      ox = (m - 1) * (W + 20)
      printf "<text x=\"%d\" y=\"18\" font-size=\"13\">%s, %s patterns</text>\n", ox + L, name, modes[m]
      printf "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"black\"/>\n", ox + L, T, W - L - 10, H - T - B
      for (db = lo; db <= hi; db += 5) {
        y = T + (H - T - B) * (1 - (db - lo) / (hi - lo))
        printf "<line x1=\"%d\" x2=\"%d\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/><text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%d</text>\n", ox + L, ox + W - 10, y, y, ox + L - 4, y + 4, db
      }
      split("0.1 0.2 0.5 1 2", ticks, " ")
      for (i = 1; i <= 5; ++i) {
        x = ox + L + (W - L - 10) * (log(ticks[i]) - xmin) / (xmax - xmin)
        printf "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%d\" y2=\"%d\" stroke=\"#ddd\"/><text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>\n", x, x, T, H - B, x, H - B + 14, ticks[i]
      }
      printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">taps per kernel pixel</text>\n", ox + L + (W - L) / 2, H - 8
      printf "<text x=\"%d\" y=\"%d\" transform=\"rotate(-90 %d %d)\" text-anchor=\"middle\">PSNR (dB) vs exact</text>\n", ox + 14, T + (H - T - B) / 2, ox + 14, T + (H - T - B) / 2
      li = 0
      for (v in colour) {
        k = modes[m] "," v; np = split(pts[k], pp, " "); line = ""
        for (i = 1; i <= np; ++i) {
          split(pp[i], xy, ":"); if (xy[2] == "null") continue
          x = ox + L + (W - L - 10) * (log(xy[1]) - xmin) / (xmax - xmin); y = T + (H - T - B) * (1 - (xy[2] - lo) / (hi - lo))
          line = line sprintf("%.1f,%.1f ", x, y)
          printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"2.5\" fill=\"%s\"/>\n", x, y, colour[v]
        }
        printf "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\"/>\n", line, colour[v]
        printf "<text x=\"%d\" y=\"%d\" fill=\"%s\">%s</text>\n", ox + L + 8, T + 16 + 14 * li++, colour[v], v
      }
    }
    print "</svg>"
  }' doc/data/bilateral_filter_study.csv > "doc/images/bilateral_filter_$name.svg"
done
echo "study in $csv, ratios in doc/data/bilateral_filter_ratios.csv, plots in doc/images/bilateral_filter_*.svg"
