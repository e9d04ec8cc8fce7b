// Test tool: how alike two PNG images are, as /work/shared/tools/imgdiff.py measures it (both
// composited over white, PSNR over RGB in [0, 1]; 99 for identical images).
//   png_psnr A.png B.png   prints "psnr=<dB> mismatch=<share of pixels off by more than 10%>"
// The images must have the same size (exit 2 otherwise, or when one cannot be read).
#include <cmath>
#include <cstdio>
#include <exception>

#include "svgmotion/png_io.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: png_psnr A.png B.png\n");
    return 2;
  }
  try {
    const svgm::RgbaImage a = svgm::read_png(argv[1]), b = svgm::read_png(argv[2]);
    if (a.width != b.width || a.height != b.height) {
      std::fprintf(stderr, "png_psnr: %s is %dx%d, %s is %dx%d\n", argv[1], a.width, a.height, argv[2], b.width,
                   b.height);
      return 2;
    }
    const size_t n = static_cast<size_t>(a.width) * a.height;
    double se = 0;
    size_t off = 0;
    for (size_t p = 0; p < n; ++p) {
      double worst = 0;
      for (int c = 0; c < 3; ++c) {
        // Over white: c * alpha + (1 - alpha).
        const double va = (a.rgba[4 * p + c] * a.rgba[4 * p + 3] / 255.0 + 255 - a.rgba[4 * p + 3]) / 255.0;
        const double vb = (b.rgba[4 * p + c] * b.rgba[4 * p + 3] / 255.0 + 255 - b.rgba[4 * p + 3]) / 255.0;
        se += (va - vb) * (va - vb);
        worst = std::fmax(worst, std::fabs(va - vb));
      }
      off += worst > 0.10;
    }
    const double mse = se / (3.0 * n);
    std::printf("psnr=%.2f mismatch=%.6f\n", mse == 0 ? 99.0 : 10 * std::log10(1 / mse), static_cast<double>(off) / n);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "png_psnr: %s\n", e.what());
    return 2;
  }
}
