#pragma once
// GLSL sources. Every surface is drawn by the same program in every pass, and
// gl_Position is invariant, so the depth a pass compares with GL_EQUAL is the
// depth the first pass wrote, bit for bit.

namespace umbra::shaders {

// What a surface pass writes (uniform `pass`). kDistance draws a shadow map
// face: seen from the light, the distance from it.
// kMarkReceiver keeps only the fragments of triangles in `receiver_plane`,
// writing nothing but the stencil (planar shadows).
enum SurfacePass { kAmbient = 0, kDirect = 1, kMaskLit = 3, kDistance = 4, kMarkReceiver = 5 };

// How the lit passes (kDirect, kMaskLit) test a point for shadow (uniform
// `shadow_test`): not at all (the stencil or nothing decides), against the
// bound cube shadow map, or by the volumes' count at the fragment's pixel.
enum ShadowTest { kNoShadowTest = 0, kShadowMapTest = 1, kVolumeCountTest = 2 };

// The texture units the surface shaders sample: a triangle's material map,
// the cube shadow map, the volumes' count, and each triangle's light code
// (SurfaceBuffers::use_light). Unit 0 is the one left active.
enum TextureUnit { kMaterialTextureUnit = 0, kShadowMapUnit = 1, kVolumeCountUnit = 2, kLightCodeUnit = 3, kShownFrameUnit = 4 };

// Phong shading shared by triangles and spheres; `n` is the surface's unit
// normal, turned here to the side facing the camera, and `s` the one it is
// shaded with: `n` itself, or where `smoothed`, a mesh's interpolated normal
// (Mesh::triangle_normals), turned to n's side. `faces_light` says whether
// the seen side faces the light: for a triangle, from the exact side of the
// light that its vertices carry (kTriangleVertex), never from n . l, whose
// rounding varies across a face in the light's plane and would speckle it.
inline constexpr const char* kShading = R"(
uniform int pass;
// Where the ray through window point (x, y) starts: window_origins * (x, y,
// 1), the eye for a perspective (window_rays in camera.hpp).
uniform mat3 window_origins;
uniform vec3 ambient_sum;      // sum over lights of their ambient intensity
// The scene's FillLight: a headlight at the eye, and a hemisphere's sky and
// ground (weighted by the seen side's turn to `sky_up`), added in the
// ambient pass, as they cast no shadow in view.
uniform vec3 headlight;
uniform vec3 sky;
uniform vec3 ground;
uniform vec3 sky_up;
uniform vec3 light_position;
uniform vec3 light_color;
uniform vec3 material_ambient;
uniform vec3 material_diffuse;
uniform vec3 material_specular;
uniform float material_shininess;
uniform bool specular_used;  // false when no material and light have a specular term
// A shadow catcher (Material::shadow_catcher) is drawn as (lit, unlit, 0, -1):
// the white light that reaches it and the light that would without shadows,
// each the mean over the channels, for the read-back to turn into the share
// the shadows take (pixel_mean.hpp's resolved_sample).
uniform bool material_catcher;
uniform int shadow_test;  // ShadowTest
// Shadow mapping (Williams 1978): a point is in shadow when it lies further
// from the light than the map's nearest surface in its direction, by more
// than a bias of two texels (slope-scaled).
uniform samplerCube shadow_map;
uniform float shadow_map_texel;  // a texel's width at distance 1: 2 / size
uniform vec4 receiver_plane;     // (n, d), n unit
uniform float receiver_tolerance;
// Shadow volumes: how many volumes hold the surface point seen at each
// pixel, counted by the volume pass; not zero is in shadow.
uniform sampler2D volume_count;
out vec4 frag_color;
// What the material's ambient and diffuse terms are multiplied by: a mesh's
// vertex colours, blended across its triangles; white for everything else.
vec3 surface_color = vec3(1.0);

// A vector's direction and length with it scaled by its largest component
// first: a light 2e19 away is 4e38 squared, past a float's range, and
// normalize() and length() square it.
float largest_component(vec3 v) { return max(max(abs(v.x), abs(v.y)), abs(v.z)); }
vec3 unit(vec3 v) {
  float m = largest_component(v);
  return m > 0.0 ? normalize(v / m) : v;
}
float safe_length(vec3 v) {
  float m = largest_component(v);
  return m > 0.0 ? m * length(v / m) : 0.0;
}

bool in_mapped_shadow(vec3 p, float n_dot_l) {
  vec3 to_p = p - light_position;
  float d = safe_length(to_p);
  float bias = 2.0 * shadow_map_texel * d / max(n_dot_l, 0.1);
  return d - bias > texture(shadow_map, to_p).r;
}

bool in_shadow(vec3 p, float n_dot_l) {
  if (shadow_test == 1) return in_mapped_shadow(p, n_dot_l);
  if (shadow_test == 2) return texelFetch(volume_count, ivec2(gl_FragCoord.xy), 0).r != 0.0;
  return false;
}

// For a point of a mesh's face that turns from the light, whether anything
// more than the mesh's own surface, where the light's ray leaves it, stands
// between it and the light: a count past that surface's one volume. A
// shadow map cannot tell them apart: the faces' shadow.
bool shadowed_past_own_surface(vec3 p, float n_dot_l) {
  if (shadow_test == 2) return abs(texelFetch(volume_count, ivec2(gl_FragCoord.xy), 0).r) > 1.5;
  return in_shadow(p, n_dot_l);
}

// Whether the side of a sphere's point `p` with normal `n` that the camera
// sees faces the light (its terminator is a curve, which no rounding moves
// by more than a pixel's part).
// Where this fragment's pixel ray starts (window_origins at gl_FragCoord),
// worked out once by main() before anything is shaded.
vec3 ray_origin;

// From `p` back along its pixel's ray to where the ray starts.
vec3 to_viewer(vec3 p) { return ray_origin - p; }

bool seen_side_faces_light(vec3 p, vec3 n) {
  if (dot(n, to_viewer(p)) < 0.0) n = -n;
  return dot(n, light_position - p) > 0.0;
}

// `on_terminator`: a smooth face on its mesh's terminator (terminator.hpp),
// where its normals, not its faces, say where the light ends.
void shade(vec3 p, vec3 n, vec3 s, bool smoothed, bool on_terminator, bool faces_light) {
  if (pass == 4) {
    frag_color = vec4(safe_length(p - light_position));
    return;
  }
  if (pass == 5) {
    if (abs(dot(receiver_plane.xyz, n)) < 0.9999 ||
        abs(dot(receiver_plane.xyz, p) + receiver_plane.w) > receiver_tolerance) discard;
    frag_color = vec4(0.0);
    return;
  }
  if (dot(n, to_viewer(p)) < 0.0) n = -n;
  if (!smoothed) s = n;
  else if (dot(s, n) < 0.0) s = -s;
  vec3 l = unit(light_position - p);
  float n_dot_l = max(dot(n, l), 0.0);  // may round below 0 where the face meets the light at a grazing angle
  // What the shading takes: n . l, or for a smooth face, s . l.
  float s_dot_l = smoothed ? max(dot(s, l), 0.0) : n_dot_l;
  // A smooth face on the terminator that turns from the light takes the
  // light its normals give it, unless more than its own surface shades it.
  bool lit_by_normals = smoothed && on_terminator && !faces_light;
  if (pass == 0) {
    vec3 ambient = ambient_sum + mix(ground, sky, 0.5 + 0.5 * dot(s, sky_up));
    vec3 head = headlight * max(dot(s, normalize(to_viewer(p))), 0.0);
    float unshadowed = dot(ambient + head, vec3(1.0 / 3.0));
    frag_color = material_catcher ? vec4(unshadowed, unshadowed, 0.0, -1.0)
                                  : vec4((ambient * material_ambient + head * material_diffuse) * surface_color, 1.0);
  } else if (pass == 1) {
    if (!faces_light && !lit_by_normals) discard;
    if (material_catcher) {
      float direct = dot(light_color, vec3(1.0 / 3.0)) * n_dot_l;
      frag_color = vec4(in_shadow(p, n_dot_l) ? 0.0 : direct, direct, 0.0, 0.0);
      return;
    }
    if (lit_by_normals ? shadowed_past_own_surface(p, n_dot_l) : in_shadow(p, n_dot_l)) discard;
    vec3 colour = material_diffuse * surface_color * s_dot_l;
    if (specular_used) {
      vec3 v = normalize(to_viewer(p));
      vec3 r = reflect(-l, s);
      float highlight = material_shininess > 0.0 ? pow(max(dot(r, v), 0.0), material_shininess) : 1.0;
      colour += material_specular * highlight;
    }
    frag_color = vec4(light_color * colour, 0.0);  // alpha, coverage, is the ambient pass's
  } else {
    if (!faces_light) discard;
    if (in_shadow(p, n_dot_l)) discard;
    frag_color = vec4(1.0);
  }
}
)";

inline constexpr const char* kTriangleVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;  // white (a constant attribute) when no mesh has vertex colours
layout(location = 3) in vec2 uv;     // texture coordinates, v down the image; (0, 0) when none
// Per triangle (gl_VertexID / 3: the triangles' vertices are drawn as
// arrays), the light's side of its plane, exactly (SurfaceBuffers::use_light),
// plus one: 2 where `normal` points, 0 the other side, 1 in the plane; and
// 4 more where a smooth mesh's triangle is on the terminator (terminator.hpp).
uniform usamplerBuffer light_codes;
#ifdef UMBRA_SMOOTH  // defined where some mesh is smooth: a flat scene interpolates nothing more
layout(location = 5) in vec3 shading_normal;  // (0, 0, 0): flat
out vec3 world_shading_normal;
flat out int on_terminator;  // 1 where the triangle is on a smooth mesh's terminator
#endif
uniform mat4 view_projection;
out vec3 world_position;
out vec3 world_normal;
flat out float plane_offset;  // n . p of the triangle's plane, for the fragment's exact point
out vec3 vertex_color;
out vec2 texture_uv;
flat out int triangle_light_side;
invariant gl_Position;
void main() {
  world_position = position;
  world_normal = normal;
  plane_offset = dot(normal, position);
  uint light_code = texelFetch(light_codes, gl_VertexID / 3).r;
  triangle_light_side = int(light_code & 3u) - 1;
#ifdef UMBRA_SMOOTH
  world_shading_normal = shading_normal;
  on_terminator = int(light_code >> 2u);
#endif
  vertex_color = color;
  texture_uv = uv;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";

// How a texture map's texel indices wrap along each axis (uniform
// `material_wrap`): the values of TextureImage::Wrap.
enum TextureWrap { kWrapRepeat = 0, kWrapClampToEdge = 1, kWrapMirroredRepeat = 2 };

// A triangle's texture map is filtered here, bilinearly without mipmaps, from
// four texelFetch reads weighted in float, as the ray-cast reference weighs
// them in double (sample_bilinear). The GL's own GL_LINEAR may weigh texels
// with a few bits of sub-texel precision, as the GL allows: llvmpipe's put
// channels two levels from the reference where neighbouring texels differ by
// most of the range (15 channels of a map of alternating extremes,
// texture_maps_test).
inline constexpr const char* kTriangleFragmentMain = R"(
uniform mat3 window_rays;  // window_rays * (x, y, 1): the ray through window point (x, y)
in vec3 world_position;
in vec3 world_normal;
flat in float plane_offset;
in vec3 vertex_color;
in vec2 texture_uv;
flat in int triangle_light_side;
#ifdef UMBRA_SMOOTH
in vec3 world_shading_normal;
flat in int on_terminator;
#endif
uniform bool material_textured;
uniform sampler2D material_texture;
uniform ivec2 material_wrap;  // TextureWrap, along u and along v
const int kWrapClampToEdge = 1, kWrapMirroredRepeat = 2;  // as in TextureWrap

// Texel index i of a row or column of n, wrapped: floor division, as GLSL's
// % is undefined for negative operands (exact while |i| < 2^23).
int wrapped(int i, int n, int wrap) {
  if (wrap == kWrapClampToEdge) return clamp(i, 0, n - 1);
  int period = wrap == kWrapMirroredRepeat ? 2 * n : n;
  int m = i - period * int(floor(float(i) / float(period)));
  m = clamp(m, 0, period - 1);
  return m < n ? m : period - 1 - m;
}

vec3 texel(ivec2 size, int i, int j) {
  return texelFetch(material_texture, ivec2(wrapped(i, size.x, material_wrap.x), wrapped(j, size.y, material_wrap.y)), 0).rgb;
}

vec3 bilinear(vec2 uv) {
  ivec2 size = textureSize(material_texture, 0);
  // Texel centres sit at (i + 1/2) / size: the point's place among them.
  vec2 p = clamp(uv * vec2(size) - 0.5, -4194304.0, 4194304.0);
  vec2 f = floor(p);
  vec2 a = p - f;
  int i = int(f.x), j = int(f.y);
  return mix(mix(texel(size, i, j), texel(size, i + 1, j), a.x),
             mix(texel(size, i, j + 1), texel(size, i + 1, j + 1), a.x), a.y);
}

void main() {
  surface_color = vertex_color;
  if (material_textured) surface_color *= bilinear(texture_uv);
  // The point the pixel's ray meets the triangle's plane, as the ray-cast
  // reference finds it: a position interpolated across a large triangle (a
  // floor millions of units wide) is off by a float's rounding of its
  // corners, far more than the point's own. Where the ray grazes the plane,
  // the interpolated one.
  vec3 ray = window_rays * vec3(gl_FragCoord.xy, 1.0);
  ray_origin = window_origins * vec3(gl_FragCoord.xy, 1.0);
  float along = dot(world_normal, ray);
  vec3 p = world_position;
  if (abs(along) > 1e-3 * length(world_normal) * length(ray)) {
    float t = (plane_offset - dot(world_normal, ray_origin)) / along;
    if (t > 0.0) p = ray_origin + t * ray;
  }
  // The camera's side of the plane: it can round only where the plane
  // nearly holds the ray's start, and the face is seen edge-on.
  int eye_side = dot(world_normal, ray_origin - p) < 0.0 ? -1 : 1;
  bool faces_light = triangle_light_side != 0 && triangle_light_side == eye_side;
  vec3 n = normalize(world_normal);
#ifdef UMBRA_SMOOTH
  // A smooth face's corners all have normals; a flat one's are all 0, and so is what is blended of them.
  bool smoothed = world_shading_normal != vec3(0.0);
  shade(p, n, smoothed ? normalize(world_shading_normal) : n, smoothed, on_terminator != 0, faces_light);
#else
  shade(p, n, n, false, false, faces_light);
#endif
}
)";

// Spheres are exact: a box around the sphere is rasterised (back faces, so it
// covers the sphere from outside and inside) and each fragment intersects its
// eye ray with the true sphere, writing the hit's depth. The ray is the one
// through the pixel's centre, from gl_FragCoord (window_rays), as
// the ray-cast reference traces it. Near the outline the hit's depth goes
// as the square root of the distance to it, so a ray aimed at a position
// interpolated across the box, which the GL computes to a precision of its
// own choosing, can be far off there: on NVIDIA's H100 up to 54 steps of the
// 24-bit depth buffer, enough to put a lit pixel behind the shadow volume
// that grazes the sphere's terminator.
inline constexpr const char* kSphereVertex = R"(#version 330 core
layout(location = 0) in vec3 corner;   // of the cube [-1,1]^3
uniform mat4 view_projection;
uniform vec3 sphere_center;
uniform float sphere_radius;
invariant gl_Position;
void main() {
  // 1% margin so the box's own rasterisation never trims the silhouette.
  gl_Position = view_projection * vec4(sphere_center + corner * sphere_radius * 1.01, 1.0);
}
)";

inline constexpr const char* kSphereFragmentMain = R"(
uniform mat4 view_projection;
uniform mat3 window_rays;  // window_rays * (x, y, 1): the ray through window point (x, y)
uniform vec3 sphere_center;
uniform float sphere_radius;
void main() {
  vec3 d = normalize(window_rays * vec3(gl_FragCoord.xy, 1.0));
  ray_origin = window_origins * vec3(gl_FragCoord.xy, 1.0);
  vec3 oc = ray_origin - sphere_center;
  float b = dot(oc, d);
  vec3 closest = oc - b * d;  // h = R^2 - |oc - b d|^2 avoids b^2 - c cancellation
  float h = sphere_radius * sphere_radius - dot(closest, closest);
  if (h < 0.0) discard;
  float s = sqrt(h);
  float t = -b - s;
  if (t <= 0.0) t = -b + s;  // the ray starts inside the sphere
  if (t <= 0.0) discard;
  vec3 p = ray_origin + t * d;
  vec4 clip = view_projection * vec4(p, 1.0);
  gl_FragDepth = 0.5 * (clip.z / clip.w) + 0.5;
  vec3 n = (p - sphere_center) / sphere_radius;
  shade(p, n, n, false, false, seen_side_faces_light(p, n));
}
)";

inline constexpr const char* kVolumeVertex = R"(#version 330 core
layout(location = 0) in vec4 position;  // w = 0: extruded, its xyz the direction P - L
uniform mat4 view_projection;
// Mesh volumes keep one static buffer whose extruded vertices hold the mesh
// point P itself; the light gives them the direction P - L here.
uniform bool extrude_from_light;
uniform vec3 light_position;
// 1 / s: an extruded vertex goes to L + s (P - L), (P - L + L / s, 1 / s)
// in homogeneous form; 0 puts it at infinity (volume_reach.hpp).
uniform float extruded_w;
invariant gl_Position;
void main() {
  vec4 p = position;
  if (position.w == 0.0) {
    vec3 direction = extrude_from_light ? position.xyz - light_position : position.xyz;
    p = vec4(direction + extruded_w * light_position, extruded_w);
  }
  gl_Position = view_projection * p;
}
)";

// Planar shadows: a caster's triangles projected along rays from the light
// onto a receiver's plane, clipped to the part strictly between the plane and
// the light (what lies beyond either casts nothing onto it).
inline constexpr const char* kPlanarVertex = R"(#version 330 core
layout(location = 0) in vec4 position;  // w = 1
uniform mat4 view_projection;
uniform mat4 shadow_matrix;
uniform vec4 plane;          // the light on its positive side
uniform float light_height;  // dot(plane, light)
uniform float plane_offset;  // nearer the plane or the light than this casts nothing
void main() {
  float h = dot(plane, position);
  gl_ClipDistance[0] = h - plane_offset;
  gl_ClipDistance[1] = light_height - h - plane_offset;
  gl_Position = view_projection * (shadow_matrix * position);
}
)";

inline constexpr const char* kVolumeFragment = R"(#version 330 core
uniform vec4 tint;
out vec4 frag_color;
void main() { frag_color = tint; }
)";

// Triangles' depth alone, where only whether samples pass the depth test
// matters (FrameDrawing::draw_nearest_surfaces's question): the position
// exactly as kTriangleVertex places it (invariant, the same expression).
inline constexpr const char* kDepthVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
uniform mat4 view_projection;
invariant gl_Position;
void main() { gl_Position = view_projection * vec4(position, 1.0); }
)";
inline constexpr const char* kDepthFragment = R"(#version 330 core
void main() {}
)";

// What the window shows of the frame (FrameTarget::show): each pixel the
// mean of its block of samples x samples, and with the soft curve, the
// surfaces' part of it toned as image/pixel_mean.hpp's put_pixel_mean tones
// a picture's (the curve of image/tone_curve.hpp, in float), over the
// colour of a sample that sees nothing. One triangle covers the window.
inline constexpr const char* kShowVertex = R"(#version 330 core
void main() { gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0); }
)";
inline constexpr const char* kShowFragment = R"(#version 330 core
uniform sampler2D frame;
uniform int samples;     // per side of a pixel's block
uniform int soft;        // 1: ToneCurve::kSoft; 0: kClip, the mean as it is
uniform float knee;      // kToneKnee
uniform vec3 nothing;    // a sample that sees no surface
out vec4 shown;
float toned(float light) {
  return light <= knee ? light : knee + (1.0 - knee) * (1.0 - exp(-(light - knee) / (1.0 - knee)));
}
void main() {
  ivec2 first = ivec2(gl_FragCoord.xy) * samples;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) sum += texelFetch(frame, first + ivec2(i, j), 0);
  vec4 mean = sum / float(samples * samples);
  vec3 colour = mean.rgb;
  if (soft == 1) {
    vec3 behind = (1.0 - mean.a) * nothing;
    vec3 surface = mean.a > 0.0 ? (colour - behind) / mean.a : vec3(0.0);
    colour = mean.a * vec3(toned(surface.r), toned(surface.g), toned(surface.b)) + behind;
  }
  shown = vec4(colour, 1.0);
}
)";

// The volume pass: each volume face adds +1 or -1 to the count at its pixel
// by additive blending, into a 32-bit float target, where whole numbers stay
// exact far past any count a frame can reach.
inline constexpr const char* kVolumeCountFragment = R"(#version 330 core
uniform float front_adds;  // what a front face adds; a back face adds the opposite
out vec4 count;
void main() { count = vec4(gl_FrontFacing ? front_adds : -front_adds); }
)";

}  // namespace umbra::shaders
