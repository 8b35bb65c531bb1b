package studio.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.sunflow.SunflowAPI;
import org.sunflow.core.display.FileDisplay;
import org.sunflow.math.Matrix4;
import org.sunflow.math.Point3;
import org.sunflow.math.Vector3;
import org.sunflow.system.UI;
import org.sunflow.system.UserInterface;

/**
 * {@code java -cp sunflow.jar:studio-bench.jar studio.bench.SunflowRender SCENE.sfs OUT.png}: replays a
 * {@link SunflowScript} through Sunflow's API and renders it to a PNG, as one process (so the peer's
 * time includes its JVM start-up, as ours does). Prints only Sunflow's errors; exit code 1 after any.
 */
public final class SunflowRender {

    private SunflowRender() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: SunflowRender SCENE.sfs OUT.png");
            System.exit(2);
        }
        int errors;
        try {
            errors = render(Path.of(args[0]), Path.of(args[1]));
        } catch (IllegalArgumentException e) {
            System.err.println(e.getMessage());
            System.exit(2);
            return;
        }
        System.exit(errors > 0 ? 1 : 0);
    }

    /**
     * Replays the script and renders it to {@code out}.
     *
     * @return how many errors Sunflow reported (printed to stderr)
     * @throws IllegalArgumentException naming the script's line if a line cannot be read
     */
    public static int render(Path script, Path out) throws IOException {
        ErrorsOnly ui = new ErrorsOnly();
        UI.set(ui);
        SunflowAPI api = new SunflowAPI();
        try (BufferedReader in = Files.newBufferedReader(script)) {
            String line;
            int number = 0;
            while ((line = in.readLine()) != null) {
                number++;
                if (!line.isBlank()) {
                    try {
                        replay(api, line.trim().split(" "));
                    } catch (RuntimeException e) {
                        throw new IllegalArgumentException(script + ":" + number + ": " + e, e);
                    }
                }
            }
        }
        api.render(SunflowAPI.DEFAULT_OPTIONS, new FileDisplay(out.toString()));
        return ui.errors;
    }

    static void replay(SunflowAPI api, String[] w) {
        switch (w[0]) {
            case "param" -> param(api, w);
            case "shader" -> api.shader(w[1], w[2]);
            case "geometry" -> api.geometry(w[1], w[2]);
            case "light" -> api.light(w[1], w[2]);
            case "camera" -> api.camera(w[1], w[2]);
            case "instance" -> api.instance(w[1], w[2]);
            case "options" -> api.options(w[1]);
            default -> throw new IllegalArgumentException("unknown command " + w[0]);
        }
    }

    private static void param(SunflowAPI api, String[] w) {
        String name = w[1];
        switch (w[2]) {
            case "string" -> api.parameter(name, w[3]);
            case "int" -> api.parameter(name, Integer.parseInt(w[3]));
            case "bool" -> api.parameter(name, Boolean.parseBoolean(w[3]));
            case "float" -> api.parameter(name, Float.parseFloat(w[3]));
            case "color" -> api.parameter(name, "sRGB linear", floats(w, 3, 3));
            case "point" -> api.parameter(name, new Point3(f(w[3]), f(w[4]), f(w[5])));
            case "vector" -> api.parameter(name, new Vector3(f(w[3]), f(w[4]), f(w[5])));
            case "matrix" -> api.parameter(name, new Matrix4(floats(w, 3, 16), true));
            case "lookat" -> api.parameter(name, Matrix4.lookAt(new Point3(f(w[3]), f(w[4]), f(w[5])),
                    new Point3(f(w[6]), f(w[7]), f(w[8])), new Vector3(f(w[9]), f(w[10]), f(w[11]))));
            case "ints" -> {
                int[] v = new int[Integer.parseInt(w[3])];
                for (int i = 0; i < v.length; i++) {
                    v[i] = Integer.parseInt(w[4 + i]);
                }
                api.parameter(name, v);
            }
            case "strings" -> {
                String[] v = new String[Integer.parseInt(w[3])];
                System.arraycopy(w, 4, v, 0, v.length);
                api.parameter(name, v);
            }
            case "floats" -> api.parameter(name, w[3], w[4], floats(w, 6, Integer.parseInt(w[5])));
            default -> throw new IllegalArgumentException("unknown parameter type " + w[2]);
        }
    }

    private static float[] floats(String[] w, int from, int count) {
        float[] v = new float[count];
        for (int i = 0; i < count; i++) {
            v[i] = Float.parseFloat(w[from + i]);
        }
        return v;
    }

    private static float f(String s) {
        return Float.parseFloat(s);
    }

    /** Sunflow's messages: errors to stderr, the rest dropped. */
    private static final class ErrorsOnly implements UserInterface {
        int errors;

        @Override
        public void print(UI.Module module, UI.PrintLevel level, String message) {
            if (level == UI.PrintLevel.ERROR) {
                errors++;
                System.err.println("sunflow: " + module + ": " + message);
            }
        }

        @Override
        public void taskStart(String s, int min, int max) {
        }

        @Override
        public void taskUpdate(int current) {
        }

        @Override
        public void taskStop() {
        }
    }
}
