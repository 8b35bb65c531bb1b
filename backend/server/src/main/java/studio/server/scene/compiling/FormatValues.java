package studio.server.scene.compiling;

import java.util.List;

import studio.engine.math.Vec3;

/** The format's values (validated already) as the engine's, and a field's default when it is left out. */
final class FormatValues {

    private FormatValues() {
    }

    static Vec3 vec(List<Double> v) {
        return new Vec3(v.get(0), v.get(1), v.get(2));
    }

    static <T> T or(T value, T fallback) {
        return value != null ? value : fallback;
    }
}
