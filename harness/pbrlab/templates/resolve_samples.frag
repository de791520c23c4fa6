#version 330 core
//@DEFINES
// The shader resolve of a float target (gpu/targets.py Target.resolve): each output pixel is
// the normalised, weighted sum of the samples around it, weight w(dx) w(dy) of the sample's
// offset (dx, dy) from the output pixel's centre, in OUTPUT pixels. The drawn target is
// u_scale times the output's size (render.supersample) and holds u_sample_count samples per
// pixel (render.antialias). Filters (render.antialias_filter):
//   box (u_filter 0): w(x) = 1 for |x| < 0.5: the output pixel's own samples, averaged;
//   blackman_harris (u_filter 1): w(x) = a0 - a1 cos(2 pi t) + a2 cos(4 pi t) - a3 cos(6 pi t),
//     t = (x + R) / (2 R) for |x| < R = 1.5 (Harris 1978, "On the Use of Windows for Harmonic
//     Analysis with the Discrete Fourier Transform", the 4-term window: a0..a3 = 0.35875,
//     0.48829, 0.14128, 0.01168); Cycles' default pixel filter, separable in x and y
//     (intern/cycles/scene/film.cpp filter_table: its width 1.5 doubled).
// Samples outside the image are left out and the weights renormalised. Linear radiance,
// premultiplied by coverage, as drawn.
#ifdef PBRLAB_SINGLE_SAMPLE
uniform sampler2D u_samples;
#define PBRLAB_FETCH(q, s) texelFetch(u_samples, q, 0)
#define PBRLAB_SIZE textureSize(u_samples, 0)
#else
uniform sampler2DMS u_samples;
#define PBRLAB_FETCH(q, s) texelFetch(u_samples, q, s)
#define PBRLAB_SIZE textureSize(u_samples)
#endif
uniform int u_sample_count;
uniform vec2 u_offsets[16];  // each sample's position in its pixel, from the pixel's centre (drawn px)
uniform int u_scale;         // drawn pixels per output pixel, per axis
uniform int u_filter;        // 0 box, 1 Blackman-Harris
out vec4 frag_color;

const float PI = 3.14159265358979;
const float BLACKMAN_HARRIS_RADIUS = 1.5;

float window(float x) {
    if (u_filter == 0) {
        return abs(x) < 0.5 ? 1.0 : 0.0;
    }
    if (abs(x) >= BLACKMAN_HARRIS_RADIUS) {
        return 0.0;
    }
    float t = 2.0 * PI * (x + BLACKMAN_HARRIS_RADIUS) / (2.0 * BLACKMAN_HARRIS_RADIUS);
    return 0.35875 - 0.48829 * cos(t) + 0.14128 * cos(2.0 * t) - 0.01168 * cos(3.0 * t);
}

void main() {
    ivec2 size = PBRLAB_SIZE;
    float scale = float(u_scale);
    vec2 centre = (floor(gl_FragCoord.xy) + 0.5) * scale;  // the output pixel's centre, drawn px
    float radius = (u_filter == 0 ? 0.5 : BLACKMAN_HARRIS_RADIUS) * scale;
    ivec2 lo = ivec2(floor(centre - radius - 0.5));
    ivec2 hi = ivec2(ceil(centre + radius + 0.5));
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
            if (x < 0 || y < 0 || x >= size.x || y >= size.y) {
                continue;
            }
            for (int s = 0; s < u_sample_count; ++s) {
                vec2 d = (vec2(x, y) + 0.5 + u_offsets[s] - centre) / scale;
                float w = window(d.x) * window(d.y);
                if (w > 0.0) {
                    sum += w * PBRLAB_FETCH(ivec2(x, y), s);
                    weights += w;
                }
            }
        }
    }
    frag_color = sum / weights;
}
