// Drawing the curd with WebGL 2: the values are one integer texture and the colours a palette
// texture, so that a colour change redraws without new data, and the canvas is drawn at the
// size it is shown (a cell a screen pixel or more, or the cell under each pixel), whatever the
// field's size.

export const fieldGl = (() => {
  const vertexSource = `#version 300 es
    out vec2 uv;
    void main() {
      // One triangle over the viewport; uv runs 0..1 over it, y up as the cells are.
      vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
      uv = p;
      gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
    }`;
  // Cell i (counted from the field's corner, x fastest) is at bit i * bits of the packed
  // values, lowest first: in texel k = i * bits / 8 of the byte texture (a 16-bit texture at
  // 16 bits, one texel a cell), at (k % rowLength, k / rowLength); its colour at
  // (value % 256, value / 256) of the palette.
  const fragmentSource = `#version 300 es
    precision highp float;
    precision highp int;
    precision highp usampler2D;
    uniform usampler2D values;
    uniform sampler2D palette;
    uniform ivec2 size;
    uniform int rowLength;
    uniform int bits;
    in vec2 uv;
    out vec4 colour;
    void main() {
      ivec2 cell = min(ivec2(floor(uv * vec2(size))), size - 1);
      int index = cell.y * size.x + cell.x;
      int k = bits == 16 ? index : index * bits / 8;
      uint word = texelFetch(values, ivec2(k % rowLength, k / rowLength), 0).r;
      uint v = bits == 16 ? word : (word >> uint(index * bits % 8)) & uint((1 << bits) - 1);
      colour = texelFetch(palette, ivec2(int(v & 255u), int(v >> 8u)), 0);
    }`;

  let gl = null, program = null, valuesTexture = null, paletteTexture = null, uniforms = null;
  let field = null;  // {w, h} of the values uploaded

  function compile(type, source) {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  }

  function setUp(canvas) {
    if (gl) return true;
    gl = canvas.getContext("webgl2", { antialias: false, preserveDrawingBuffer: true, alpha: false });
    if (!gl) return false;
    program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER, vertexSource));
    gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragmentSource));
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
    uniforms = {};
    for (const name of ["values", "palette", "size", "rowLength", "bits"]) uniforms[name] = gl.getUniformLocation(program, name);
    const texture = () => {
      const t = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
      return t;
    };
    valuesTexture = texture();
    paletteTexture = texture();
    return true;
  }

  // The packed values (bytes, `bits` a cell of w x h) as the texture: bytes, or 16-bit words
  // at 16 bits; rows as long as the GPU allows, padded where the count does not fill the last.
  function upload(bytes, bits, w, h) {
    const wide = bits === 16;
    const n = wide ? w * h : bytes.length;
    const rowLength = Math.min(n, gl.getParameter(gl.MAX_TEXTURE_SIZE));
    const rows = Math.ceil(n / rowLength);
    let data = wide ? new Uint16Array(bytes.buffer, bytes.byteOffset, n) : bytes;
    if (rows * rowLength !== n) {
      const padded = new data.constructor(rows * rowLength);
      padded.set(data);
      data = padded;
    }
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, valuesTexture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, wide ? gl.R16UI : gl.R8UI, rowLength, rows, 0, gl.RED_INTEGER,
                  wide ? gl.UNSIGNED_SHORT : gl.UNSIGNED_BYTE, data);
    field = { w, h, rowLength, bits };
  }

  // colours: [r, g, b] per value, value 0 first.
  function setPalette(colours) {
    const rows = Math.max(1, Math.ceil(colours.length / 256));
    const rgba = new Uint8Array(256 * rows * 4);
    colours.forEach((c, v) => rgba.set([c[0], c[1], c[2], 255], v * 4));
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, paletteTexture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 256, rows, 0, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
  }

  function render() {
    gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
    gl.useProgram(program);
    gl.uniform1i(uniforms.values, 0);
    gl.uniform1i(uniforms.palette, 1);
    gl.uniform2i(uniforms.size, field.w, field.h);
    gl.uniform1i(uniforms.rowLength, field.rowLength);
    gl.uniform1i(uniforms.bits, field.bits);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.finish();  // the pixels are drawn when draw() returns, as the page's timing says
  }

  return {
    // Draws the packed values (`bits` a cell, w x h) with `colours` on the canvas, whose pixel
    // size the caller set.
    draw(canvas, values, bits, w, h, colours) {
      if (!setUp(canvas)) return false;
      upload(values, bits, w, h);
      setPalette(colours);
      render();
      return true;
    },
    // The same values in new colours: no new data.
    recolour(colours) {
      if (!gl || !field) return false;
      setPalette(colours);
      render();
      return true;
    },
  };
})();
