package studio.server.scene.compiling;

import studio.engine.render.RenderRequest;
import studio.engine.render.RenderSettings;
import studio.engine.scene.Scene;

/**
 * A validated scene mapped onto the engine, with how to write the result.
 *
 * @param format   "png" or "jpg"
 * @param quality  JPEG quality in [0, 1]
 * @param fileStem the scene's name made safe for a file name or a header
 */
public record CompiledScene(Scene scene, RenderSettings settings, String format, double quality, String fileStem) {

    public String fileName() {
        return fileStem + "." + format;
    }

    public String mediaType() {
        return format.equals("jpg") ? "image/jpeg" : "image/png";
    }

    /** The whole render of this scene with its settings, into a new film (see {@link RenderRequest}). */
    public RenderRequest request() {
        return RenderRequest.of(scene, settings);
    }
}
