package studio.server.asset;

import java.net.URI;
import java.time.Duration;
import java.util.List;

import org.springframework.http.CacheControl;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.http.ResponseEntity;
import org.springframework.web.bind.annotation.GetMapping;
import org.springframework.web.bind.annotation.PathVariable;
import org.springframework.web.bind.annotation.PostMapping;
import org.springframework.web.bind.annotation.RequestBody;
import org.springframework.web.bind.annotation.RequestHeader;
import org.springframework.web.bind.annotation.RequestMapping;
import org.springframework.web.bind.annotation.RequestMethod;
import org.springframework.web.bind.annotation.RestController;
import org.springframework.web.context.request.WebRequest;

import jakarta.servlet.http.HttpServletRequest;
import studio.server.system.IntakeMemory;

/**
 * POST /api/assets: raw bytes in (their media type as Content-Type), checked and kept by their
 * content's hash: 201 with Location the first time, 200 with the same body after; a glTF model's
 * answer lists what it holds that is not drawn in {@code warnings}. HEAD tells whether
 * an asset is kept (200 or 404); GET returns its bytes, immutable (the ETag is the id). Whoever knows
 * an id may read it: ids are hashes of content the caller had.
 */
@RestController
class AssetController {

    /**
     * What an upload answers.
     *
     * @param warnings what a glTF model holds that is not drawn (skins, animations, extensions...); empty for
     *                 every other kind
     */
    record AssetView(String id, long bytes, String mediaType, List<String> warnings) {
        static AssetView of(Asset asset, List<String> warnings) {
            return new AssetView(asset.id(), asset.bytes().length, asset.type().mediaType(), warnings);
        }
    }

    private static final CacheControl IMMUTABLE = CacheControl.maxAge(Duration.ofDays(365)).immutable();

    private final AssetStore store;
    private final AssetChecks checks;
    private final long maxBytes;

    AssetController(AssetStore store, AssetChecks checks, AssetLimits limits) {
        this.store = store;
        this.checks = checks;
        this.maxBytes = limits.maxBytes();
    }

    @PostMapping("/api/assets")
    ResponseEntity<AssetView> upload(@RequestBody(required = false) byte[] body,
                                     @RequestHeader(value = HttpHeaders.CONTENT_TYPE, required = false) String contentType,
                                     HttpServletRequest request) {
        AssetType type = AssetType.ofMediaType(contentType);
        if (type == null) {
            throw AssetRefusedException.unsupported(contentType);
        }
        byte[] bytes = body != null ? body : new byte[0];
        if (bytes.length > maxBytes) {
            throw AssetRefusedException.tooLarge(bytes.length, maxBytes);
        }
        List<String> warnings = checks.check(type, bytes, IntakeMemory.of(request), store.meshes()::bytes);
        Asset asset = Asset.of(type, bytes);
        Asset kept = store.get(asset.id());
        if (kept != null) {
            return ResponseEntity.ok(AssetView.of(kept, warnings));
        }
        boolean added = store.put(asset);
        AssetView view = AssetView.of(asset, warnings);
        return added ? ResponseEntity.created(URI.create("/api/assets/" + asset.id())).body(view)
                : ResponseEntity.ok(view);
    }

    @RequestMapping(path = "/api/assets/{id}", method = RequestMethod.HEAD)
    ResponseEntity<Void> head(@PathVariable String id) {
        Asset asset = store.get(AssetIds.require(id));
        if (asset == null) {
            return ResponseEntity.notFound().build();
        }
        return ResponseEntity.ok().contentType(MediaType.parseMediaType(asset.type().mediaType()))
                .contentLength(asset.bytes().length).eTag(asset.id()).cacheControl(IMMUTABLE).build();
    }

    @GetMapping("/api/assets/{id}")
    ResponseEntity<byte[]> get(@PathVariable String id, WebRequest request) {
        Asset asset = store.get(AssetIds.require(id));
        if (asset == null) {
            throw AssetRefusedException.notFound(id);
        }
        if (request.checkNotModified("\"" + asset.id() + "\"")) {
            return ResponseEntity.status(304).eTag(asset.id()).cacheControl(IMMUTABLE).build();
        }
        return ResponseEntity.ok().contentType(MediaType.parseMediaType(asset.type().mediaType()))
                .eTag(asset.id()).cacheControl(IMMUTABLE).body(asset.bytes());
    }
}
