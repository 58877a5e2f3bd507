// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-png-check SHOT.png: exit 0 when a screenshot of a crash report is not blank: more than 5 % of its
// pixels are not background white, and some are the reds of the dent colour map (the pictures are shown,
// not just the text). Prints the counts.
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include <cstdio>

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::fprintf(stderr, "usage: crumple-png-check SHOT.png\n");
        return 2;
    }
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(argv[1], &width, &height, &channels, 3);
    if (pixels == nullptr)
    {
        std::fprintf(stderr, "crumple-png-check: cannot read %s\n", argv[1]);
        return 2;
    }
    long inked = 0, red = 0;
    const long total = static_cast<long>(width) * height;
    for (long i = 0; i < total; ++i)
    {
        const int r = pixels[3 * i], g = pixels[3 * i + 1], b = pixels[3 * i + 2];
        inked += (r < 235 || g < 235 || b < 235) ? 1 : 0;
        red += (r > 120 && r > g + 60 && r > b + 60) ? 1 : 0;
    }
    stbi_image_free(pixels);
    std::printf("%d x %d: %ld non-white pixels (%.1f %%), %ld red\n", width, height, inked, 100.0 * inked / total, red);
    return inked > total / 20 && red > 1000 ? 0 : 1;
}
