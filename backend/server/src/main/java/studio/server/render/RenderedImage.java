package studio.server.render;

/** An encoded image with what the client needs to save it and the render's figures. */
public record RenderedImage(byte[] bytes, String mediaType, String fileName, int width, int height,
                            long elapsedMillis, double raysPerSecond) {
}
