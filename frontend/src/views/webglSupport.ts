/** What the browser's WebGL is: whether WebGL 2 is there at all, and whether it draws in software. */

/** What {@link probeWebgl} found. */
export interface WebglSupport {
  webgl2: boolean;
  /** The GPU's name says it is a software rasterizer (no graphics card does the drawing). */
  software: boolean;
}

const SOFTWARE = /SwiftShader|llvmpipe|softpipe|Software Rasterizer|Microsoft Basic Render/i;

/** Whether a WebGL renderer name (`UNMASKED_RENDERER_WEBGL`) is a software rasterizer. */
export function isSoftwareRenderer(name: string): boolean {
  return SOFTWARE.test(name);
}

/** Probes for WebGL 2 and its renderer's name, without letting three.js log its own error. */
export function probeWebgl(): WebglSupport {
  try {
    const gl = document.createElement('canvas').getContext('webgl2');
    if (!gl) return { webgl2: false, software: false };
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER) ?? '');
    gl.getExtension('WEBGL_lose_context')?.loseContext();
    return { webgl2: true, software: isSoftwareRenderer(name) };
  } catch {
    return { webgl2: false, software: false };
  }
}
