// One triangle over the whole viewport at the far plane (depth 1): the background pass draws it
// after the scene with depth test LEQUAL, so that it covers only where camera rays miss.
out vec2 vNdc;

void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
  vNdc = p;
  gl_Position = vec4(p, 1.0, 1.0);
}
