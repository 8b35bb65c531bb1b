package studio.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/**
 * Calls of Sunflow's scene API (org.sunflow.SunflowAPI), one per line, for {@link SunflowRender}
 * to replay in its own process: Debian's Sunflow has no scene-file parser, and the benchmark's
 * own process never loads Sunflow. Names and strings must not contain white space.
 *
 * <pre>
 * param NAME string|int|bool|float VALUE
 * param NAME color R G B              (linear sRGB)
 * param NAME point|vector X Y Z
 * param NAME matrix M00 M01 ... M33   (row-major)
 * param NAME lookat EX EY EZ TX TY TZ UX UY UZ   (Matrix4.lookAt(eye, target, up))
 * param NAME ints N V...
 * param NAME strings N V...
 * param NAME floats TYPE INTERPOLATION N V...    (TYPE: point, vector, ...; e.g. "point vertex")
 * shader|geometry|light|camera NAME TYPE
 * instance NAME GEOMETRY
 * options NAME
 * </pre>
 */
public final class SunflowScript {

    private final StringBuilder text = new StringBuilder();

    public SunflowScript param(String name, String value) {
        return line("param", name, "string", word(value));
    }

    public SunflowScript param(String name, int value) {
        return line("param", name, "int", Integer.toString(value));
    }

    public SunflowScript param(String name, boolean value) {
        return line("param", name, "bool", Boolean.toString(value));
    }

    public SunflowScript param(String name, double value) {
        return line("param", name, "float", Sdl.num(value));
    }

    public SunflowScript color(String name, Rgb c) {
        return line("param", name, "color", Sdl.num(c.r()), Sdl.num(c.g()), Sdl.num(c.b()));
    }

    public SunflowScript point(String name, Vec3 p) {
        return line("param", name, "point", Sdl.num(p.x()), Sdl.num(p.y()), Sdl.num(p.z()));
    }

    public SunflowScript vector(String name, Vec3 v) {
        return line("param", name, "vector", Sdl.num(v.x()), Sdl.num(v.y()), Sdl.num(v.z()));
    }

    /** A 4x4 matrix, row-major. */
    public SunflowScript matrix(String name, double[] rowMajor) {
        if (rowMajor.length != 16) {
            throw new IllegalArgumentException("a 4x4 matrix has 16 elements");
        }
        text.append("param ").append(word(name)).append(" matrix");
        for (double v : rowMajor) {
            text.append(' ').append(Sdl.num(v));
        }
        text.append('\n');
        return this;
    }

    public SunflowScript lookAt(String name, Vec3 eye, Vec3 target, Vec3 up) {
        return line("param", name, "lookat", Sdl.num(eye.x()), Sdl.num(eye.y()), Sdl.num(eye.z()),
                Sdl.num(target.x()), Sdl.num(target.y()), Sdl.num(target.z()), Sdl.num(up.x()), Sdl.num(up.y()),
                Sdl.num(up.z()));
    }

    public SunflowScript ints(String name, int[] values) {
        text.append("param ").append(word(name)).append(" ints ").append(values.length);
        for (int v : values) {
            text.append(' ').append(v);
        }
        text.append('\n');
        return this;
    }

    public SunflowScript strings(String name, String... values) {
        text.append("param ").append(word(name)).append(" strings ").append(values.length);
        for (String v : values) {
            text.append(' ').append(word(v));
        }
        text.append('\n');
        return this;
    }

    /** Per-vertex data, e.g. {@code floats("points", "point", "vertex", xyz)}. */
    public SunflowScript floats(String name, String type, String interpolation, double[] values) {
        text.append("param ").append(word(name)).append(" floats ").append(word(type)).append(' ')
                .append(word(interpolation)).append(' ').append(values.length);
        for (double v : values) {
            text.append(' ').append(Float.toString((float) v));
        }
        text.append('\n');
        return this;
    }

    public SunflowScript shader(String name, String type) {
        return line("shader", name, type);
    }

    public SunflowScript geometry(String name, String type) {
        return line("geometry", name, type);
    }

    public SunflowScript instance(String name, String geometry) {
        return line("instance", name, geometry);
    }

    public SunflowScript light(String name, String type) {
        return line("light", name, type);
    }

    public SunflowScript camera(String name, String type) {
        return line("camera", name, type);
    }

    public SunflowScript options(String name) {
        return line("options", name);
    }

    public String text() {
        return text.toString();
    }

    public void write(Path file) throws IOException {
        Files.writeString(file, text);
    }

    private SunflowScript line(String... words) {
        for (int i = 0; i < words.length; i++) {
            text.append(i == 0 ? "" : " ").append(word(words[i]));
        }
        text.append('\n');
        return this;
    }

    private static String word(String s) {
        if (s.isEmpty() || s.chars().anyMatch(Character::isWhitespace)) {
            throw new IllegalArgumentException("a Sunflow script word must be non-empty without white space: '" + s + "'");
        }
        return s;
    }
}
