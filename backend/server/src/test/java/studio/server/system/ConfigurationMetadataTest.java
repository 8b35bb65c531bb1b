package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * The studio.* properties' metadata, which the configuration processor writes from the properties'
 * Javadoc for IDEs and operators: every property has a description, and every studio.* key that
 * application.properties sets is a known property.
 */
class ConfigurationMetadataTest {

    private static JsonNode metadata() throws Exception {
        try (InputStream in = ConfigurationMetadataTest.class.getResourceAsStream("/META-INF/spring-configuration-metadata.json")) {
            assertThat(in).as("the configuration processor's metadata on the class path").isNotNull();
            return JsonMapper.builder().build().readTree(in);
        }
    }

    private static List<JsonNode> studioProperties() throws Exception {
        List<JsonNode> studio = new ArrayList<>();
        for (JsonNode property : metadata().get("properties")) {
            if (property.get("name").asString().startsWith("studio.")) {
                studio.add(property);
            }
        }
        return studio;
    }

    @Test
    void everyStudioPropertyIsDescribed() throws Exception {
        List<JsonNode> studio = studioProperties();
        assertThat(studio).hasSizeGreaterThan(25);
        for (JsonNode property : studio) {
            String description = property.path("description").asString("");
            assertThat(description).as(property.get("name").asString()).isNotBlank().doesNotContain("{@");
        }
    }

    @Test
    void everyStudioKeyOfApplicationPropertiesIsAKnownProperty() throws Exception {
        Set<String> known = new TreeSet<>();
        for (JsonNode property : studioProperties()) {
            known.add(property.get("name").asString());
        }
        Properties application = new Properties();
        try (Reader in = Files.newBufferedReader(Path.of("src/main/resources/application.properties"), StandardCharsets.UTF_8)) {
            application.load(in);
        }
        Set<String> set = new TreeSet<>();
        for (String key : application.stringPropertyNames()) {
            if (key.startsWith("studio.")) {
                set.add(key);
            }
        }
        assertThat(set).hasSizeGreaterThan(20);
        assertThat(known).containsAll(set);
    }
}
