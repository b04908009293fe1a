#version 330 core
// Two directional lights (key and fill), a sky/ground hemisphere ambient and a soft specular;
// a texture multiplies the base colour; a highlight tints the selected part.
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;

uniform vec4 u_color;
uniform bool u_textured;
uniform sampler2D u_texture;
uniform vec3 u_eye;
uniform vec3 u_highlight;
uniform float u_highlight_amount;
uniform float u_ambient_boost;

out vec4 frag_color;

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 base = u_color.rgb;
  if (u_textured) base *= texture(u_texture, v_uv).rgb;
  vec3 v = normalize(u_eye - v_world);
  vec3 key = normalize(vec3(0.45, 0.35, 0.85));
  vec3 fill = normalize(vec3(-0.6, -0.45, 0.35));
  float d_key = max(dot(n, key), 0.0);
  float d_fill = max(dot(n, fill), 0.0);
  float hemi = 0.5 + 0.5 * n.z;
  vec3 ambient = mix(vec3(0.20, 0.19, 0.18), vec3(0.36, 0.38, 0.42), hemi) + u_ambient_boost;
  vec3 h = normalize(key + v);
  float spec = pow(max(dot(n, h), 0.0), 40.0) * 0.22;
  vec3 c = base * (ambient + 0.70 * d_key + 0.25 * d_fill) + vec3(spec);
  c = mix(c, u_highlight, u_highlight_amount);
  frag_color = vec4(c, u_color.a);
}
