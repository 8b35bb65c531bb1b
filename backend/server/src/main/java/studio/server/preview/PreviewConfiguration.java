package studio.server.preview;

import io.micrometer.core.instrument.Gauge;
import io.micrometer.core.instrument.binder.MeterBinder;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;
import org.springframework.web.socket.config.annotation.EnableWebSocket;
import org.springframework.web.socket.config.annotation.WebSocketConfigurer;
import org.springframework.web.socket.config.annotation.WebSocketHandlerRegistry;

import studio.server.render.RenderBudget;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.security.SignIn;
import studio.server.system.StudioProperties;
import tools.jackson.databind.json.JsonMapper;

/** The live view's WebSocket endpoint, {@code /api/preview}, with its limits. */
@Configuration(proxyBeanMethods = false)
@EnableWebSocket
@EnableConfigurationProperties(PreviewProperties.class)
class PreviewConfiguration implements WebSocketConfigurer {

    private final PreviewHandler handler;
    private final SessionLimit sessionLimit;
    private final PrincipalViews principalViews;

    PreviewConfiguration(SceneCompiler compiler, RenderBudget budget, StudioProperties studio, PreviewProperties limits,
                         JsonMapper json, SignIn signIn) {
        this.handler = new PreviewHandler(new PreviewRenderer(compiler, budget, studio.renderThreads(), limits, json),
                studio.limits().maxBodyBytes(), limits.maxSessions(), limits.idleTimeout());
        this.principalViews = new PrincipalViews(signIn.maxLiveViewsPerPrincipal(limits.maxSessions()));
        this.sessionLimit = new SessionLimit(handler, limits.maxSessions(), json, principalViews);
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
        registry.addHandler(principalViews.releasingOnClose(handler), "/api/preview").addInterceptors(sessionLimit);
    }
}
