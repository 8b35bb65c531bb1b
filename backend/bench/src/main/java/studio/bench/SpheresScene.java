package studio.bench;

import java.util.Locale;
import java.util.Random;

/**
 * The "10,000 spheres" benchmark scene, as a scene file: a grid of n x n small chalk and plastic
 * spheres (random radius and colour from a fixed palette, fixed seed), all in view from above at an
 * angle, against the background. There is no ground plane: the server's default object limit
 * (studio.limits.max-objects) is 10,000, and the CLI applies the default limits.
 */
public final class SpheresScene {

    static final String[] PALETTE = {"#c0392b", "#2e86c1", "#27ae60", "#f1c40f", "#8e44ad", "#ecf0f1", "#d35400"};
    static final long SEED = 20240611L;

    private SpheresScene() {
    }

    /** The scene file's JSON for an n x n grid (n = 100: 10,000 spheres). */
    public static String json(int n) {
        Random random = new Random(SEED);
        double spacing = 1.0;
        double half = (n - 1) * spacing / 2;
        StringBuilder json = new StringBuilder(128 * n * n + 1024);
        json.append("{\n  \"version\": 1,\n  \"name\": \"spheres-").append(n * n).append("\",\n");
        json.append(String.format(Locale.ROOT, "  \"camera\": { \"position\": [0, %s, %s], \"lookAt\": [0, 0, %s], "
                + "\"up\": [0, 1, 0], \"fov\": 40 },%n", num(1.0 * n), num(1.1 * n), num(0.05 * n)));
        json.append("  \"background\": \"#1c2028\",\n  \"ambient\": 0.1,\n");
        json.append(String.format(Locale.ROOT, "  \"lights\": [%n    { \"type\": \"point\", \"position\": [%s, %s, %s], "
                        + "\"color\": \"#ffffff\", \"intensity\": 0.8 },%n    { \"type\": \"point\", \"position\": [%s, %s, %s], "
                        + "\"color\": \"#ffd8a8\", \"intensity\": 0.3 }%n  ],%n", num(0.3 * n), num(0.6 * n), num(0.4 * n),
                num(-0.4 * n), num(0.5 * n), num(-0.2 * n)));
        json.append("  \"objects\": [\n");
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double r = 0.25 + 0.2 * random.nextDouble();
                double x = -half + i * spacing + 0.3 * (random.nextDouble() - 0.5);
                double z = -half + j * spacing + 0.3 * (random.nextDouble() - 0.5);
                String color = PALETTE[random.nextInt(PALETTE.length)];
                String material = random.nextBoolean()
                        ? "{ \"type\": \"chalk\", \"color\": \"" + color + "\" }"
                        : "{ \"type\": \"plastic\", \"color\": \"" + color + "\" }";
                json.append("    { \"type\": \"sphere\", \"center\": [").append(num(x)).append(", ").append(num(r))
                        .append(", ").append(num(z)).append("], \"radius\": ").append(num(r)).append(", \"material\": ")
                        .append(material).append(" }").append(i == n - 1 && j == n - 1 ? "\n" : ",\n");
            }
        }
        json.append("  ]\n}\n");
        return json.toString();
    }

    /** Six decimals at most, enough for the layout and short. */
    private static String num(double v) {
        return Sdl.num(Math.round(v * 1e6) / 1e6);
    }
}
