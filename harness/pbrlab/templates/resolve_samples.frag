#version 330 core
// The filtered resolve of a multisampled float target (render.antialias_filter
// "blackman_harris"; gpu/targets.py): each output pixel is the normalised, weighted sum of the
// samples of the pixels around it, weight w(dx) w(dy) of the sample's offset (dx, dy) in pixels
// from the output pixel's centre, w the Blackman-Harris window over [-RADIUS, RADIUS]:
//   w(x) = a0 - a1 cos(2 pi t) + a2 cos(4 pi t) - a3 cos(6 pi t), t = (x + RADIUS) / (2 RADIUS)
// (Harris 1978, "On the Use of Windows for Harmonic Analysis with the Discrete Fourier
// Transform", the 4-term window: a0..a3 = 0.35875, 0.48829, 0.14128, 0.01168). Cycles' default
// pixel filter is this window 1.5 px wide on each side of the pixel centre, separable in x and y
// (intern/cycles/scene/film.cpp filter_table: the width doubled). Samples outside the image are
// left out and the weights renormalised. Linear radiance, premultiplied by coverage, as drawn.
uniform sampler2DMS u_samples;
uniform int u_sample_count;
uniform vec2 u_offsets[16];  // each sample's position in its pixel, from the pixel's centre (px)
uniform float u_radius;      // the window's half-width (px)
out vec4 frag_color;

const float PI = 3.14159265358979;

float blackman_harris(float x) {
    if (abs(x) >= u_radius) {
        return 0.0;
    }
    float t = 2.0 * PI * (x + u_radius) / (2.0 * u_radius);
    return 0.35875 - 0.48829 * cos(t) + 0.14128 * cos(2.0 * t) - 0.01168 * cos(3.0 * t);
}

void main() {
    ivec2 size = textureSize(u_samples);
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int reach = int(ceil(u_radius + 0.5));  // neighbours whose samples can lie within the window
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
            ivec2 q = pixel + ivec2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) {
                continue;
            }
            for (int s = 0; s < u_sample_count; ++s) {
                vec2 d = vec2(dx, dy) + u_offsets[s];
                float w = blackman_harris(d.x) * blackman_harris(d.y);
                if (w > 0.0) {
                    sum += w * texelFetch(u_samples, q, s);
                    weights += w;
                }
            }
        }
    }
    frag_color = sum / weights;
}
