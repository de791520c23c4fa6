// examples/wgpu: one triangle that covers the viewport (vertices at clip (-1, -1), (3, -1),
// (-1, 3)); the fragment program ray-traces its sphere per pixel and discards the misses.
@vertex
fn main(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    let corner = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return vec4<f32>(corner * 2.0 - 1.0, 0.0, 1.0);
}
