package studio.bench.accuracy;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.VectorGraphicsEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.XYStyler;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The speed-against-accuracy charts: per scene, RMSE against median render time on log-log axes,
 * one line per method with a marker at each measurement; written as PNG and SVG per scene, and
 * all scenes as one PNG.
 */
final class BenchCharts {

    /** One scene's chart, and one panel of the combined image (kept small so the PNG stays well under 150 KB). */
    static final int WIDTH = 560, HEIGHT = 400, PANEL_WIDTH = 500, PANEL_HEIGHT = 360;
    private static final Color ADAPTIVE_COLOR = Color.BLACK;
    private static final Color POVRAY_COLOR = new Color(0x7f7f7f);

    /** One colour and marker per sampler (in the order of EngineFeatures.SAMPLER_NAMES), the same in every panel. */
    private static final Color[] COLORS = {
        new Color(0x1f77b4), new Color(0xff7f0e), new Color(0x2ca02c), new Color(0xd62728),
        new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x17becf),
    };
    private static final Marker[] MARKERS = {
        SeriesMarkers.CIRCLE, SeriesMarkers.SQUARE, SeriesMarkers.DIAMOND, SeriesMarkers.TRIANGLE_UP,
        SeriesMarkers.TRIANGLE_DOWN, SeriesMarkers.PLUS, SeriesMarkers.OVAL, SeriesMarkers.RECTANGLE,
    };

    private BenchCharts() {
    }

    /**
     * Writes {@code speed-accuracy-SCENE.png} and {@code .svg} for each scene and
     * {@code speed-accuracy.png} with every scene, two panels a row.
     *
     * @return the files written
     */
    static List<Path> write(Path dir, Map<String, List<Measurement>> rowsByScene) throws IOException {
        List<XYChart> panels = new ArrayList<>();
        List<Path> written = new ArrayList<>();
        for (Map.Entry<String, List<Measurement>> scene : rowsByScene.entrySet()) {
            XYChart chart = chart(scene.getKey(), scene.getValue(), WIDTH, HEIGHT);
            Path png = dir.resolve("speed-accuracy-" + scene.getKey() + ".png");
            writeSmallPng(BitmapEncoder.getBufferedImage(chart), png);
            Path svg = dir.resolve("speed-accuracy-" + scene.getKey() + ".svg");
            try (OutputStream out = Files.newOutputStream(svg)) {
                VectorGraphicsEncoder.saveVectorGraphic(chart, out, VectorGraphicsEncoder.VectorGraphicsFormat.SVG);
            }
            written.add(png);
            written.add(svg);
            panels.add(chart(scene.getKey(), scene.getValue(), PANEL_WIDTH, PANEL_HEIGHT));
        }
        if (!panels.isEmpty()) {
            Path all = dir.resolve("speed-accuracy.png");
            writeSmallPng(grid(panels, 2), all);
            written.add(all);
        }
        return written;
    }

    /** The panels side by side, {@code columns} a row, on white. */
    static BufferedImage grid(List<XYChart> panels, int columns) {
        int cols = Math.min(columns, panels.size()), rows = (panels.size() + cols - 1) / cols;
        int w = panels.get(0).getWidth(), h = panels.get(0).getHeight();
        BufferedImage image = new BufferedImage(cols * w, rows * h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, image.getWidth(), image.getHeight());
            for (int i = 0; i < panels.size(); i++) {
                g.drawImage(BitmapEncoder.getBufferedImage(panels.get(i)), (i % cols) * w, (i / cols) * h, null);
            }
        } finally {
            g.dispose();
        }
        return image;
    }

    /** A PNG at the strongest deflate level (ImageIO's default is a faster, weaker one). */
    static void writeSmallPng(BufferedImage image, Path file) throws IOException {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("png").next();
        try (OutputStream stream = Files.newOutputStream(file);
             ImageOutputStream out = new MemoryCacheImageOutputStream(stream)) {
            writer.setOutput(out);
            ImageWriteParam param = writer.getDefaultWriteParam();
            if (param.canWriteCompressed()) {
                param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
                param.setCompressionQuality(0f); // 0: smallest file
            }
            writer.write(null, new IIOImage(image, null, null), param);
        } finally {
            writer.dispose();
        }
    }

    /** The methods of one scene: the samplers in their fixed order, then adaptive sampling. */
    private static List<String> methods(List<Measurement> rows) {
        Set<String> methods = new LinkedHashSet<>();
        rows.forEach(m -> methods.add(m.method()));
        return List.copyOf(methods);
    }

    static XYChart chart(String scene, List<Measurement> rows, int width, int height) {
        XYChart chart = new XYChartBuilder().width(width).height(height).title(scene)
                .xAxisTitle("median render time (ms)").yAxisTitle("RMSE (linear light)").build();
        XYStyler style = chart.getStyler();
        style.setXAxisLogarithmic(true);
        style.setYAxisLogarithmic(true);
        style.setLegendPosition(Styler.LegendPosition.OutsideE);
        style.setLegendBorderColor(Color.WHITE);
        style.setLegendFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        style.setChartBackgroundColor(Color.WHITE);
        style.setPlotBackgroundColor(Color.WHITE);
        style.setPlotGridLinesColor(new Color(0xe4e4e4));
        style.setPlotGridLinesStroke(new BasicStroke(0.5f));
        style.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 14));
        style.setAxisTitleFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        style.setAxisTickLabelsFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
        style.setMarkerSize(7);
        for (String method : methods(rows)) {
            // a log axis cannot show 0: a render identical to the reference has no point on the chart
            List<Measurement> own = BenchSummary.ordered(rows.stream()
                    .filter(m -> m.method().equals(method) && m.rmse() > 0 && m.medianMillis() > 0).toList());
            if (own.isEmpty()) {
                continue;
            }
            XYSeries series = chart.addSeries(method,
                    own.stream().mapToDouble(Measurement::medianMillis).toArray(),
                    own.stream().mapToDouble(Measurement::rmse).toArray());
            series.setLineWidth(1.5f);
            if (method.startsWith("povray")) {
                // POV-Ray in grey, apart from every method of ours: a solid grid, a dotted adaptive line
                series.setLineColor(POVRAY_COLOR);
                series.setMarkerColor(POVRAY_COLOR);
                boolean adaptive = !Double.isNaN(own.get(0).threshold());
                series.setMarker(adaptive ? SeriesMarkers.DIAMOND : SeriesMarkers.SQUARE);
                if (adaptive) {
                    series.setLineStyle(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f,
                            new float[] {2f, 3f}, 0f));
                }
            } else if (Double.isNaN(own.get(0).threshold())) {
                int i = Math.max(0, EngineFeatures.SAMPLER_NAMES.indexOf(method));
                series.setLineColor(COLORS[i % COLORS.length]);
                series.setMarkerColor(COLORS[i % COLORS.length]);
                series.setMarker(MARKERS[i % MARKERS.length]);
            } else {
                series.setLineColor(ADAPTIVE_COLOR);
                series.setMarkerColor(ADAPTIVE_COLOR);
                if (Method.isBySamples(method)) {
                    // the default threshold as the most samples a pixel may take moves: a solid line
                    series.setMarker(SeriesMarkers.TRIANGLE_UP);
                } else {
                    series.setMarker(SeriesMarkers.CROSS);
                    series.setLineStyle(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f,
                            new float[] {6f, 4f}, 0f));
                }
            }
        }
        return chart;
    }
}
