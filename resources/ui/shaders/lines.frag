#version 330 core
in vec4 v_color;
uniform bool u_round_points;
uniform float u_alpha;
out vec4 frag_color;

void main() {
  if (u_round_points) {
    vec2 d = gl_PointCoord - vec2(0.5);
    if (dot(d, d) > 0.25) discard;
  }
  frag_color = vec4(v_color.rgb, v_color.a * u_alpha);
}
