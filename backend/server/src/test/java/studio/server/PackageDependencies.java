package studio.server;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Which classes each class of a module uses, by two witnesses: its source's imports (an import
 * that is not used still says what the file means to use, and a constant's use leaves no trace in
 * the class file) and its class file's constant pool (every class it names in code, signatures and
 * annotations, imported or written out in full). Test code only: no library, as the JDK reads both.
 */
final class PackageDependencies {

    private static final Pattern IMPORT = Pattern.compile("^import\\s+(?:static\\s+)?([\\w.]+?)(?:\\.\\*)?\\s*;",
            Pattern.MULTILINE);
    private static final Pattern TYPE_IN_DESCRIPTOR = Pattern.compile("L([A-Za-z_$][\\w/$]*)[;<]");

    /** One use: {@code from} (a class) uses {@code to} (a class or package), as {@code how} shows. */
    record Use(String from, String to, String how) {
        @Override
        public String toString() {
            return from + " -> " + to + " (" + how + ")";
        }
    }

    private PackageDependencies() {
    }

    /** Every use by the module whose sources are under {@code sources} and whose classes hold {@code anyClass}. */
    static List<Use> of(Path sources, Class<?> anyClass) {
        List<Use> uses = new ArrayList<>();
        uses.addAll(imports(sources));
        uses.addAll(classFileReferences(anyClass));
        return uses;
    }

    static List<Use> imports(Path sources) {
        List<Use> uses = new ArrayList<>();
        try (Stream<Path> files = Files.walk(sources)) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).sorted().toList()) {
                String from = sources.relativize(file).toString().replace('/', '.').replaceAll("\\.java$", "");
                Matcher m = IMPORT.matcher(Files.readString(file));
                while (m.find()) {
                    uses.add(new Use(from, m.group(1), "import"));
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return uses;
    }

    /** The classes named in the constant pools of the class files beside {@code anyClass} (a folder or a jar). */
    static List<Use> classFileReferences(Class<?> anyClass) {
        Path root;
        try {
            root = Path.of(anyClass.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
        List<Use> uses = new ArrayList<>();
        try (FileSystem jar = Files.isDirectory(root) ? null : FileSystems.newFileSystem(root)) {
            Path classes = jar != null ? jar.getPath("/") : root;
            try (Stream<Path> files = Files.walk(classes)) {
                for (Path file : files.filter(f -> f.toString().endsWith(".class")).sorted().toList()) {
                    String from = classes.relativize(file).toString().replace('/', '.').replaceAll("\\.class$", "");
                    try (InputStream in = Files.newInputStream(file)) {
                        for (String to : namedClasses(in)) {
                            uses.add(new Use(from, to, "class file"));
                        }
                    }
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return uses;
    }

    /** The classes a class file names: its Class entries and the types in its descriptors and signatures. */
    private static Set<String> namedClasses(InputStream classFile) throws IOException {
        DataInputStream in = new DataInputStream(classFile);
        in.readInt(); // magic
        in.readUnsignedShort(); // minor
        in.readUnsignedShort(); // major
        int count = in.readUnsignedShort();
        String[] utf8 = new String[count];
        List<Integer> classNames = new ArrayList<>();
        for (int i = 1; i < count; i++) {
            int tag = in.readUnsignedByte();
            switch (tag) {
                case 1 -> utf8[i] = in.readUTF();
                case 7 -> classNames.add(in.readUnsignedShort());
                case 8, 16, 19, 20 -> in.readUnsignedShort();
                case 3, 4, 9, 10, 11, 12, 17, 18 -> in.readInt();
                case 15 -> {
                    in.readUnsignedByte();
                    in.readUnsignedShort();
                }
                case 5, 6 -> {
                    in.readLong();
                    i++; // takes two entries
                }
                default -> throw new IOException("unknown constant pool tag " + tag);
            }
        }
        Set<String> named = new TreeSet<>();
        for (int index : classNames) {
            String name = utf8[index];
            if (!name.startsWith("[")) {
                named.add(name.replace('/', '.'));
            }
        }
        for (String text : utf8) {
            if (text != null) {
                Matcher m = TYPE_IN_DESCRIPTOR.matcher(text);
                while (m.find()) {
                    named.add(m.group(1).replace('/', '.'));
                }
            }
        }
        return named;
    }

    /** The package of a class name (its nested classes' too): the part before the first capitalised segment. */
    static String packageOf(String className) {
        StringBuilder pkg = new StringBuilder();
        for (String part : className.split("\\.")) {
            if (part.isEmpty() || Character.isUpperCase(part.charAt(0)) || part.equals("package-info")) {
                break;
            }
            pkg.append(pkg.length() > 0 ? "." : "").append(part);
        }
        return pkg.toString();
    }

    /** A cycle in a graph of names, as its path (first name repeated at the end), or null if there is none. */
    static List<String> cycle(Map<String, Set<String>> edges) {
        Map<String, Integer> state = new TreeMap<>(); // 1: on the path, 2: done
        for (String start : edges.keySet()) {
            List<String> path = new ArrayList<>();
            List<String> found = visit(start, edges, state, path);
            if (found != null) {
                return found;
            }
        }
        return null;
    }

    private static List<String> visit(String node, Map<String, Set<String>> edges, Map<String, Integer> state,
                                      List<String> path) {
        Integer seen = state.get(node);
        if (seen != null && seen == 2) {
            return null;
        }
        if (seen != null) {
            List<String> cycle = new ArrayList<>(path.subList(path.indexOf(node), path.size()));
            cycle.add(node);
            return cycle;
        }
        state.put(node, 1);
        path.add(node);
        for (String next : edges.getOrDefault(node, Set.of())) {
            List<String> found = visit(next, edges, state, path);
            if (found != null) {
                return found;
            }
        }
        path.remove(path.size() - 1);
        state.put(node, 2);
        return null;
    }
}
