import { defineConfig } from 'vite';

export default defineConfig({
  base: '/',
  build: {
    outDir: 'dist',
    emptyOutDir: true,
    chunkSizeWarningLimit: 1200,
    // uPlot is shared by the plots and tuning pages: its chunk is named after it, not after whichever page module Rollup meets first.
    rollupOptions: { output: { manualChunks: (id) => (id.includes('/node_modules/uplot/') ? 'uplot' : undefined) } },
  },
  server: { proxy: { '/api': { target: 'http://127.0.0.1:5080', ws: true } } },
});
