// Runs the tile walker beside its reference (the walker as first written)
// on every object count from 0 to +max and random ones, each under a random
// enable pattern, and compares them clock by clock: what the board uses of
// each output (addresses only in a window, landing addresses only when a
// word lands). Writes "windows W lands L reads R mismatches X" to results.txt
// and the first mismatches, one a line.
module tb_tile_walker;
    parameter M = 2;
    parameter AW = 9;
    parameter T = 8;
    parameter TAW = 3;
    parameter LAT = 2;
    localparam LANES = 2 * M - 1;
    reg clk = 0, start = 0, enable = 0;
    reg [AW:0] objects = 0;
    wire sweeping [0:1], window [0:1], finished [0:1], row_buffer [0:1], column_buffer [0:1], re [0:1];
    wire [AW-1:0] row [0:1], first [0:1], addr [0:1];
    wire [LANES-1:0] valid [0:1];
    wire [TAW-1:0] row_local [0:1], land_addr [0:1];
    wire [LANES*TAW-1:0] columns_local [0:1];
    wire [1:0] land_column [0:1], land_row [0:1];
    tile_walker #(.M(M), .AW(AW), .T(T), .TAW(TAW), .LAT(LAT)) dut (
        .clk(clk), .start(start), .enable(enable), .objects(objects),
        .sweeping(sweeping[0]), .window(window[0]), .finished(finished[0]),
        .row(row[0]), .first(first[0]), .valid(valid[0]), .row_local(row_local[0]),
        .columns_local(columns_local[0]), .row_buffer(row_buffer[0]), .column_buffer(column_buffer[0]),
        .ssram_re(re[0]), .ssram_addr(addr[0]), .land_column(land_column[0]), .land_row(land_row[0]),
        .land_addr(land_addr[0]));
    tile_walker_reference #(.M(M), .AW(AW), .T(T), .TAW(TAW), .LAT(LAT)) reference (
        .clk(clk), .start(start), .enable(enable), .objects(objects),
        .sweeping(sweeping[1]), .window(window[1]), .finished(finished[1]),
        .row(row[1]), .first(first[1]), .valid(valid[1]), .row_local(row_local[1]),
        .columns_local(columns_local[1]), .row_buffer(row_buffer[1]), .column_buffer(column_buffer[1]),
        .ssram_re(re[1]), .ssram_addr(addr[1]), .land_column(land_column[1]), .land_row(land_row[1]),
        .land_addr(land_addr[1]));

    integer out, seed, max, extra, run, runs, cycle, rate, windows, lands, reads, mismatches, idle;
    task check;
        input [8*16-1:0] what;
        input ok;
        begin
            if (!ok) begin
                mismatches = mismatches + 1;
                if (mismatches <= 20)
                    $fwrite(out, "objects %0d cycle %0d: %0s differs\n", objects, cycle, what);
            end
        end
    endtask
    task compare;
        begin
            check("sweeping", sweeping[0] == sweeping[1]);
            check("window", window[0] == window[1]);
            check("finished", finished[0] == finished[1]);
            check("valid", valid[0] == valid[1]);
            check("ssram_re", re[0] == re[1]);
            check("land_column", land_column[0] == land_column[1]);
            check("land_row", land_row[0] == land_row[1]);
            if (window[1]) begin
                check("row", row[0] == row[1]);
                check("first", first[0] == first[1]);
                check("row_local", row_local[0] == row_local[1]);
                check("columns_local", columns_local[0] == columns_local[1]);
                check("row_buffer", row_buffer[0] == row_buffer[1]);
                check("column_buffer", column_buffer[0] == column_buffer[1]);
            end
            if (re[1]) check("ssram_addr", addr[0] == addr[1]);
            if (land_column[1] != 0 || land_row[1] != 0) check("land_addr", land_addr[0] == land_addr[1]);
            if (window[1] && enable) windows = windows + 1;
            if (land_column[1] != 0) lands = lands + 1;
            if (re[1]) reads = reads + 1;
        end
    endtask
    task clock;
        begin
            #1 compare;
            #1 clk = 1;
            #1 clk = 0;
            cycle = cycle + 1;
        end
    endtask

    initial begin
        if (!$value$plusargs("seed=%d", seed)) seed = 1;
        if (!$value$plusargs("max=%d", max)) max = 4 * T + 3;
        if (!$value$plusargs("extra=%d", extra)) extra = 10;
        out = $fopen("results.txt", "w");
        windows = 0;
        lands = 0;
        reads = 0;
        mismatches = 0;
        runs = max + 1 + extra;
        for (run = 0; run < runs; run = run + 1) begin
            objects = run <= max ? run : $urandom(seed) % (1 << AW);
            rate = run % 4 == 0 ? 100 : 30 + $urandom(seed) % 70;   // percent of clocks that are slots
            cycle = 0;
            start = 1;
            enable = 0;
            clock;
            start = 0;
            idle = 0;
            // Run past the end marker by a few slots, so that a walker that went on would show.
            while (idle < 4 * (LAT + 2)) begin
                enable = ($urandom(seed) % 100) < rate;
                clock;
                if (finished[1] && enable) idle = idle + 1;
            end
        end
        $fwrite(out, "windows %0d lands %0d reads %0d mismatches %0d\n", windows, lands, reads, mismatches);
        $fclose(out);
        $finish;
    end
endmodule
