package studio.server.scene.compiling;

import studio.engine.math.Rgb;

/** The format's colours as the engine's. */
public final class Colors {

    private Colors() {
    }

    /** "#rrggbb" (already validated) in linear light. (The peer benchmark uses it too.) */
    public static Rgb linear(String hex) {
        int rgb = Integer.parseInt(hex.substring(1), 16);
        return Rgb.fromSrgb8(rgb >> 16 & 0xff, rgb >> 8 & 0xff, rgb & 0xff);
    }
}
