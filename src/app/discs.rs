//! Every disc in one instanced draw call: a unit quad drawn once per disc,
//! each instance carrying its centre and radius (px) and colour; the
//! fragment shader cuts the anti-aliased disc out of the quad. Drawn with
//! miniquad under macroquad's current camera and render target, between
//! macroquad's own batches (flushed first), so screenshots, the side panel
//! and everything drawn before and after keep their order.

use super::camera::Camera;
use super::cull::{circle_on_screen, MIN_DISC_PIXELS};
use impulse::World;
use macroquad::miniquad::{
    Bindings, BlendFactor, BlendState, BlendValue, BufferLayout, BufferSource, BufferType,
    BufferUsage, Equation, Pipeline, PipelineParams, RenderingBackend, ShaderMeta, ShaderSource,
    UniformBlockLayout, UniformDesc, UniformType, UniformsSource, VertexAttribute, VertexFormat,
    VertexStep,
};
use macroquad::prelude::{get_internal_gl, Mat4};

/// One disc as the GPU gets it: centre x, y and radius (px), RGBA.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instance {
    /// Centre x, y and radius, in pixels.
    pub disc: [f32; 3],
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
            color: [k.r, k.g, k.b, 255],
        });
    }
}

const VERTEX: &str = r#"#version 100
attribute vec2 corner;
attribute vec3 disc;
attribute vec4 color0;
uniform mat4 Projection;
varying lowp vec4 color;
varying highp vec2 local;
varying highp float radius;
void main() {
    // One pixel of margin for the anti-aliased edge.
    highp float r = disc.z + 1.0;
    local = corner * r;
    radius = disc.z;
    color = color0 / 255.0;
    gl_Position = Projection * vec4(disc.xy + local, 0.0, 1.0);
}
"#;

const FRAGMENT: &str = r#"#version 100
precision highp float;
varying lowp vec4 color;
varying highp vec2 local;
varying highp float radius;
void main() {
    float coverage = clamp(radius + 0.5 - length(local), 0.0, 1.0);
    gl_FragColor = vec4(color.rgb, color.a * coverage);
}
"#;

#[repr(C)]
struct Uniforms {
    projection: Mat4,
}

/// The GPU side: pipeline, the quad, and an instance buffer that grows.
pub struct DiscBatch {
    pipeline: Pipeline,
    bindings: Bindings,
    capacity: usize,
    /// This frame's instances (kept to reuse the allocation).
    pub instances: Vec<Instance>,
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
                        uniforms: vec![UniformDesc::new("Projection", UniformType::Mat4)],
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
        ctx.apply_uniforms(UniformsSource::table(&Uniforms { projection }));
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
        let camera = Camera::fitting(world.laws.size, DVec2::new(800.0, 800.0), 0.0);
        let mut out = Vec::new();
        instances(&world, &camera, |_| impulse::Color::palette(3), &mut out);
        assert_eq!(out.len(), 2, "the disc at x = -500 m is off screen");
        assert_eq!(out[0].disc, [400.0, 400.0, 1.0], "centre, at least 1 px");
        assert_eq!(out[1].disc, [480.0, 400.0, 16.0], "8 px per metre");
        let k = impulse::Color::palette(3);
        assert_eq!(out[1].color, [k.r, k.g, k.b, 255]);
        assert_eq!(std::mem::size_of::<Instance>(), 16, "as the layout says");
    }
}
