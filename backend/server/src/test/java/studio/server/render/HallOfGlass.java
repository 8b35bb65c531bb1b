package studio.server.render;

import java.util.Locale;
import java.util.Random;
import java.util.StringJoiner;

/**
 * A scene whose every camera sample is expensive: glass spheres between four mirrors under 20
 * lights, 16 bounces deep (about a tenth of a millisecond a sample on one thread). A 16 x 16 image
 * is a single tile, and at 256 samples that tile alone takes several seconds: only a render that
 * stops inside a tile stops soon.
 */
final class HallOfGlass {

    private HallOfGlass() {
    }

    static String scene(int size, int samples) {
        Random random = new Random(7);
        StringJoiner objects = new StringJoiner(",\n");
        for (int i = 0; i < 60; i++) {
            objects.add(String.format(Locale.ROOT, "{\"type\": \"sphere\", \"center\": [%.3f, %.3f, %.3f], "
                    + "\"radius\": %.3f, \"material\": {\"type\": \"glass\", \"ior\": 1.5}}", random.nextDouble(-4, 4),
                    random.nextDouble(0.3, 4), random.nextDouble(-4, 4), random.nextDouble(0.2, 0.5)));
        }
        int[][] normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}};
        for (int[] n : normals) {
            objects.add(String.format(Locale.ROOT, "{\"type\": \"plane\", \"point\": [%d, %d, %d], "
                    + "\"normal\": [%d, %d, %d], \"material\": {\"type\": \"mirror\", \"color\": \"#ffffff\"}}",
                    -5 * n[0], -5 * n[1], -5 * n[2], n[0], n[1], n[2]));
        }
        objects.add("{\"type\": \"plane\", \"material\": {\"type\": \"chalk\", \"color\": \"#808080\"}}");
        StringJoiner lights = new StringJoiner(",\n");
        for (int i = 0; i < 20; i++) {
            lights.add(String.format(Locale.ROOT, "{\"type\": \"point\", \"position\": [%.3f, %.3f, %.3f], "
                    + "\"color\": \"#ffffff\", \"intensity\": 0.05}", random.nextDouble(-4, 4),
                    random.nextDouble(4, 6), random.nextDouble(-4, 4)));
        }
        return """
                {"image": {"width": %d, "height": %d},
                 "render": {"sampler": "jittered", "samples": %d, "maxDepth": 16},
                 "camera": {"position": [0, 2, 4.5], "lookAt": [0, 1.5, 0], "up": [0, 1, 0], "fov": 60},
                 "lights": [%s],
                 "objects": [%s]}
                """.formatted(size, size, samples, lights, objects);
    }
}
