//! Every disc in one instanced draw call: a unit quad drawn once per disc,
//! each instance carrying its centre and radius (px), how far it has turned
//! and its colour; the fragment shader cuts the anti-aliased disc out of the
//! quad and, when spin is shown, draws the radius line that turns with the
//! disc (dark on a light fill, white on a dark one). The line costs no
//! draw call and no work on the CPU, so 10⁵ discs cost what they did; it is
//! left off discs under about 5 px in radius, where it would only darken
//! them, and fades in up to 8 px. Drawn with
//! miniquad under macroquad's current camera and render target, between
//! macroquad's own batches (flushed first), so screenshots, the side panel
//! and everything drawn before and after keep their order.

use super::cull::{circle_on_screen, MIN_DISC_PIXELS};
use crate::app::model::camera::Camera;
use impulse::World;
use macroquad::miniquad::{
    Bindings, BlendFactor, BlendState, BlendValue, BufferLayout, BufferSource, BufferType,
    BufferUsage, Equation, Pipeline, PipelineParams, RenderingBackend, ShaderMeta, ShaderSource,
    UniformBlockLayout, UniformDesc, UniformType, UniformsSource, VertexAttribute, VertexFormat,
    VertexStep,
};
use macroquad::prelude::{get_internal_gl, Mat4};

/// One disc as the GPU gets it: centre x, y and radius (px), how far it
/// has turned, RGBA.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instance {
    /// Centre x, y and radius, in pixels.
    pub disc: [f32; 3],
    /// How far the disc has turned (rad, counter-clockwise in the world),
    /// in [0, 2π): where its spin line points.
    pub angle: f32,
    /// Colour, 0–255 each.
    pub color: [u8; 4],
}

/// The discs to draw this frame, culled to the viewport, each at least
/// [`MIN_DISC_PIXELS`] in radius. `color(i)` gives disc `i`'s colour.
pub fn instances(
    world: &World,
    camera: &Camera,
    color: impl Fn(usize) -> impulse::Color,
    out: &mut Vec<Instance>,
) {
    out.clear();
    for (i, p) in world.particles.iter().enumerate() {
        let c = camera.world_to_screen(p.pos);
        let r = camera.length_in_pixels(p.radius).max(MIN_DISC_PIXELS);
        if !circle_on_screen(c, r, camera.screen_rect()) {
            continue;
        }
        let k = color(i);
        out.push(Instance {
            disc: [c.x as f32, c.y as f32, r as f32],
            // Reduced in f64: a disc that has turned for long has a large
            // angle, which f32 would hold too coarsely.
            angle: p.angle.rem_euclid(std::f64::consts::TAU) as f32,
            color: [k.r, k.g, k.b, 255],
        });
    }
}

const VERTEX: &str = r#"#version 100
attribute vec2 corner;
attribute vec3 disc;
attribute float angle0;
attribute vec4 color0;
uniform mat4 Projection;
uniform float SpinLine;
varying lowp vec4 color;
varying highp vec2 local;
varying highp float radius;
varying highp vec2 spoke;
varying highp float spoke_half;
void main() {
    // One pixel of margin for the anti-aliased edge.
    highp float r = disc.z + 1.0;
    local = corner * r;
    radius = disc.z;
    color = color0 / 255.0;
    // The world's y is up, the screen's down.
    spoke = vec2(cos(angle0), -sin(angle0));
    // Half the line's width: SpinLine, a little more on a big disc; none
    // under 4 px of radius, fading in up to 8 px.
    spoke_half = max(SpinLine, 0.03 * disc.z) * clamp((disc.z - 4.0) / 4.0, 0.0, 1.0);
    if (SpinLine <= 0.0) {
        spoke_half = 0.0;
    }
    gl_Position = Projection * vec4(disc.xy + local, 0.0, 1.0);
}
"#;

const FRAGMENT: &str = r#"#version 100
precision highp float;
varying lowp vec4 color;
varying highp vec2 local;
varying highp float radius;
varying highp vec2 spoke;
varying highp float spoke_half;
void main() {
    float coverage = clamp(radius + 0.5 - length(local), 0.0, 1.0);
    // Distance to the segment from the centre to the rim along the spoke.
    float along = clamp(dot(local, spoke), 0.0, radius);
    float off = length(local - along * spoke);
    float line = spoke_half > 0.0 ? clamp(spoke_half + 0.5 - off, 0.0, 1.0) : 0.0;
    // Ink that reads on the fill: near-black on a light one, white on a dark one.
    float light = dot(color.rgb, vec3(0.2126, 0.7152, 0.0722));
    vec3 ink = light > 0.5 ? vec3(0.08, 0.08, 0.08) : vec3(1.0, 1.0, 1.0);
    gl_FragColor = vec4(mix(color.rgb, ink, line), color.a * coverage);
}
"#;

#[repr(C)]
struct Uniforms {
    projection: Mat4,
    /// Half the spin line's width (px); 0: no spin lines.
    spin_line: f32,
}

/// The GPU side: pipeline, the quad, and an instance buffer that grows.
pub struct DiscBatch {
    pipeline: Pipeline,
    bindings: Bindings,
    capacity: usize,
    /// This frame's instances (kept to reuse the allocation).
    pub instances: Vec<Instance>,
    /// Half the width of the spin lines (px); 0 draws none.
    pub spin_line: f32,
}

impl DiscBatch {
    /// Compiles the shader and makes the buffers; needs the window.
    pub fn new() -> Self {
        // SAFETY: macroquad's documented way to reach miniquad; called on the
        // window's thread, inside the frame loop.
        let gl = unsafe { get_internal_gl() };
        let ctx = gl.quad_context;
        let shader = ctx
            .new_shader(
                ShaderSource::Glsl {
                    vertex: VERTEX,
                    fragment: FRAGMENT,
                },
                ShaderMeta {
                    images: vec![],
                    uniforms: UniformBlockLayout {
                        uniforms: vec![
                            UniformDesc::new("Projection", UniformType::Mat4),
                            UniformDesc::new("SpinLine", UniformType::Float1),
                        ],
                    },
                },
            )
            .unwrap_or_else(|e| panic!("the disc shader does not compile: {e}"));
        let pipeline = ctx.new_pipeline(
            &[
                BufferLayout::default(),
                BufferLayout {
                    step_func: VertexStep::PerInstance,
                    ..Default::default()
                },
            ],
            &[
                VertexAttribute::with_buffer("corner", VertexFormat::Float2, 0),
                VertexAttribute::with_buffer("disc", VertexFormat::Float3, 1),
                VertexAttribute::with_buffer("angle0", VertexFormat::Float1, 1),
                VertexAttribute::with_buffer("color0", VertexFormat::Byte4, 1),
            ],
            shader,
            PipelineParams {
                color_blend: Some(BlendState::new(
                    Equation::Add,
                    BlendFactor::Value(BlendValue::SourceAlpha),
                    BlendFactor::OneMinusValue(BlendValue::SourceAlpha),
                )),
                ..Default::default()
            },
        );
        let corners: [[f32; 2]; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
        let quad = ctx.new_buffer(
            BufferType::VertexBuffer,
            BufferUsage::Immutable,
            BufferSource::slice(&corners),
        );
        let indices: [u16; 6] = [0, 1, 2, 0, 2, 3];
        let index_buffer = ctx.new_buffer(
            BufferType::IndexBuffer,
            BufferUsage::Immutable,
            BufferSource::slice(&indices),
        );
        let capacity = 1024;
        let per_disc = new_instance_buffer(ctx, capacity);
        DiscBatch {
            pipeline,
            bindings: Bindings {
                vertex_buffers: vec![quad, per_disc],
                index_buffer,
                images: vec![],
            },
            capacity,
            instances: Vec::new(),
            spin_line: 0.0,
        }
    }

    /// Draws [`Self::instances`] in one call, after whatever macroquad has
    /// batched so far, on the render target and camera in use.
    pub fn draw(&mut self) {
        if self.instances.is_empty() {
            return;
        }
        // SAFETY: as in `new`.
        let mut gl = unsafe { get_internal_gl() };
        gl.flush();
        let pass = gl.quad_gl.get_active_render_pass();
        let projection = gl.quad_gl.get_projection_matrix();
        let ctx = gl.quad_context;
        if self.instances.len() > self.capacity {
            ctx.delete_buffer(self.bindings.vertex_buffers[1]);
            self.capacity = self.instances.len().next_power_of_two();
            self.bindings.vertex_buffers[1] = new_instance_buffer(ctx, self.capacity);
        }
        ctx.buffer_update(
            self.bindings.vertex_buffers[1],
            BufferSource::slice(&self.instances),
        );
        ctx.begin_pass(pass, macroquad::miniquad::PassAction::Nothing);
        ctx.apply_pipeline(&self.pipeline);
        ctx.apply_bindings(&self.bindings);
        ctx.apply_uniforms(UniformsSource::table(&Uniforms {
            projection,
            spin_line: self.spin_line,
        }));
        ctx.draw(0, 6, self.instances.len() as i32);
        ctx.end_render_pass();
    }
}

fn new_instance_buffer(
    ctx: &mut dyn RenderingBackend,
    capacity: usize,
) -> macroquad::miniquad::BufferId {
    ctx.new_buffer(
        BufferType::VertexBuffer,
        BufferUsage::Stream,
        BufferSource::empty::<Instance>(capacity),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;
    use impulse::Particle;

    #[test]
    fn off_screen_discs_are_left_out_and_tiny_ones_kept_at_a_pixel() {
        let mut world = World::new(DVec2::new(100.0, 100.0));
        let disc = |x: f64, r: f64| {
            Particle::new(
                DVec2::new(x, 50.0),
                DVec2::ZERO,
                1.0,
                r,
                impulse::Color::palette(0),
            )
        };
        world.particles = vec![disc(50.0, 0.001), disc(-500.0, 1.0), disc(60.0, 2.0)];
        world.particles[2].angle = -0.5 * std::f64::consts::PI; // a quarter turn clockwise
        let camera = Camera::fitting(world.laws.size, DVec2::new(800.0, 800.0), 0.0);
        let mut out = Vec::new();
        instances(&world, &camera, |_| impulse::Color::palette(3), &mut out);
        assert_eq!(out.len(), 2, "the disc at x = -500 m is off screen");
        assert_eq!(out[0].disc, [400.0, 400.0, 1.0], "centre, at least 1 px");
        assert_eq!(out[1].disc, [480.0, 400.0, 16.0], "8 px per metre");
        assert_eq!(out[0].angle, 0.0);
        let three_quarters = (1.5 * std::f64::consts::PI) as f32;
        assert_eq!(out[1].angle, three_quarters, "within one turn, forwards");
        let k = impulse::Color::palette(3);
        assert_eq!(out[1].color, [k.r, k.g, k.b, 255]);
        assert_eq!(std::mem::size_of::<Instance>(), 20, "as the layout says");
    }
}
