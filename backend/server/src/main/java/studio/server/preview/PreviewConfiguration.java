package studio.server.preview;

import java.nio.charset.StandardCharsets;
import java.util.Map;

import io.micrometer.core.instrument.Gauge;
import io.micrometer.core.instrument.binder.MeterBinder;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;
import org.springframework.http.HttpHeaders;
import org.springframework.http.HttpStatus;
import org.springframework.http.MediaType;
import org.springframework.http.server.ServerHttpRequest;
import org.springframework.http.server.ServerHttpResponse;
import org.springframework.web.socket.WebSocketHandler;
import org.springframework.web.socket.config.annotation.EnableWebSocket;
import org.springframework.web.socket.config.annotation.WebSocketConfigurer;
import org.springframework.web.socket.config.annotation.WebSocketHandlerRegistry;
import org.springframework.web.socket.server.HandshakeInterceptor;

import studio.server.render.RenderBudget;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.StudioProperties;
import tools.jackson.databind.json.JsonMapper;

/** The live view's WebSocket endpoint, {@code /api/preview}, with its limits. */
@Configuration(proxyBeanMethods = false)
@EnableWebSocket
@EnableConfigurationProperties(PreviewProperties.class)
class PreviewConfiguration implements WebSocketConfigurer {

    static final int RETRY_AFTER_SECONDS = 5;

    private final PreviewHandler handler;
    private final PreviewProperties limits;

    PreviewConfiguration(SceneCompiler compiler, RenderBudget budget, StudioProperties studio, PreviewProperties limits,
                         JsonMapper json) {
        this.limits = limits;
        this.handler = new PreviewHandler(new PreviewRenderer(compiler, budget, studio.renderThreads(), limits, json),
                studio.limits().maxBodyBytes(), limits.maxSessions(), limits.idleTimeout());
    }

    @Bean(destroyMethod = "close")
    PreviewHandler previewHandler() {
        return handler;
    }

    /** The live views open now, in the metrics: studio_live_view_sessions. */
    @Bean
    MeterBinder liveViewMetrics() {
        return registry -> Gauge.builder("studio.live_view.sessions", handler, PreviewHandler::open)
                .description("Live views (/api/preview) open now").register(registry);
    }

    @Override
    public void registerWebSocketHandlers(WebSocketHandlerRegistry registry) {
        registry.addHandler(handler, "/api/preview").addInterceptors(new SessionLimit());
    }

    /** Refuses the upgrade with 503 and Retry-After while {@code studio.preview.max-sessions} views are open. */
    private final class SessionLimit implements HandshakeInterceptor {

        @Override
        public boolean beforeHandshake(ServerHttpRequest request, ServerHttpResponse response, WebSocketHandler target,
                                       Map<String, Object> attributes) throws Exception {
            if (handler.tryOpen()) {
                return true;
            }
            response.setStatusCode(HttpStatus.SERVICE_UNAVAILABLE);
            response.getHeaders().set(HttpHeaders.RETRY_AFTER, Integer.toString(RETRY_AFTER_SECONDS));
            response.getHeaders().setContentType(MediaType.APPLICATION_PROBLEM_JSON);
            response.getBody().write(("{\"type\":\"about:blank\",\"title\":\"Service Unavailable\",\"status\":503,"
                    + "\"detail\":\"this server has " + limits.maxSessions() + " live views open, as many as it serves "
                    + "(studio.preview.max-sessions); try again in " + RETRY_AFTER_SECONDS + " s\","
                    + "\"instance\":\"/api/preview\"}").getBytes(StandardCharsets.UTF_8));
            return false;
        }

        @Override
        public void afterHandshake(ServerHttpRequest request, ServerHttpResponse response, WebSocketHandler target,
                                   Exception failure) {
            if (failure != null) {
                handler.release();
            }
        }
    }
}
