package studio.server.scene.examples;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

import org.springframework.core.io.Resource;
import org.springframework.core.io.support.PathMatchingResourcePatternResolver;

/** The example scenes shipped in the jar (copied from scenes/ at build time), by file stem. */
public final class ExampleScenes {

    private final Map<String, byte[]> byName;

    private ExampleScenes(Map<String, byte[]> byName) {
        this.byName = Collections.unmodifiableMap(byName);
    }

    /** Loads every scenes/*.json on the classpath. */
    public static ExampleScenes fromClasspath() {
        Map<String, byte[]> scenes = new TreeMap<>();
        try {
            for (Resource r : new PathMatchingResourcePatternResolver().getResources("classpath*:scenes/*.json")) {
                String file = r.getFilename();
                if (file == null) {
                    continue;
                }
                try (InputStream in = r.getInputStream()) {
                    scenes.put(file.substring(0, file.length() - ".json".length()), in.readAllBytes());
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the example scenes", e);
        }
        return new ExampleScenes(scenes);
    }

    public List<String> names() {
        return List.copyOf(byName.keySet());
    }

    public Optional<byte[]> get(String name) {
        return Optional.ofNullable(byName.get(name));
    }
}
